#!/usr/bin/env python3
"""Checks that no #include crosses a dependency a folder's README does not allow.

Each library folder's README.md has one line starting "May depend on:" that names, in
backticks, the project folders its files may include (`base/`, `renderer/scene/`) and the
guarded external libraries it may include (`<embree3/>`). A folder may always include itself. A README may
also have a line "Public headers:" naming, in backticks, the only files of the folder that
other folders may include (the rest are private to it, as OSL keeps its include/OSL/).
Includes of project headers are spelled from the repository root ("renderer/scene/frame.h");
a bare name ("parse_state.h") is the folder's own. Prints every crossing as
file:line: error: ... and exits 1 if there is any.
"""

import argparse
import os
import re
import sys

# The library folders, most specific first, so that renderer/scene/x.h belongs to renderer/scene.
FOLDERS = [
    "base", "renderer/rib", "renderer/geometry", "renderer/scene", "renderer/raytrace",
    "renderer/image", "renderer/shading", "renderer/frame", "renderer/photon", "renderer/pathtrace",
    "shaderlang", "brdfsim", "spectral", "viewer", "imageio/oiio", "imageio/exr", "imageio", "farm",
    "cli",
]
# External libraries only some folders may see: the build keeps them private to those.
GUARDED = ["embree3", "OpenImageIO", "OpenEXR", "tiffio.h", "png.h", "Eigen", "httplib.h",
           "nlohmann"]
SOURCE_SUFFIXES = (".h", ".cpp", ".y", ".l")
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^">]+)[">]')


def allowed_of(root, folder):
    """The folders and guarded libraries `folder` may include, from its README."""
    readme = os.path.join(root, folder, "README.md")
    try:
        with open(readme, encoding="utf-8") as f:
            text = f.read()
    except OSError:
        raise SystemExit(f"{readme}: error: cannot read the README that names the dependencies")
    match = re.search(r"^May depend on:(.*?)(?:\n\s*\n|\Z)", text, re.M | re.S)
    if not match:
        raise SystemExit(f"{readme}: error: no line starting 'May depend on:'")
    items = re.findall(r"`([^`]+)`", match.group(1))
    folders = {i.rstrip("/") for i in items if i.endswith("/") and not i.startswith("<")}
    guarded = {i.strip("<>/") for i in items if i.startswith("<")}
    unknown = folders - set(FOLDERS)
    if unknown:
        raise SystemExit(f"{readme}: error: unknown folder(s) {sorted(unknown)} in 'May depend on'")
    return folders | {folder}, guarded


def public_headers_of(root, folder):
    """The headers other folders may include from `folder`, or None when all of them."""
    try:
        with open(os.path.join(root, folder, "README.md"), encoding="utf-8") as f:
            text = f.read()
    except OSError:
        return None
    match = re.search(r"^Public headers:(.*?)(?:\n\s*\n|\Z)", text, re.M | re.S)
    return set(re.findall(r"`([^`]+)`", match.group(1))) if match else None


def owner(path):
    """The library folder a root-relative include path belongs to, or None."""
    for folder in FOLDERS:
        if path.startswith(folder + "/"):
            return folder
    return None


def check_folder(root, folder, public):
    folders, guarded = allowed_of(root, folder)
    errors = []
    for directory, subfolders, files in os.walk(os.path.join(root, folder)):
        # A subfolder that is a library of its own (imageio/oiio) is checked as that library.
        subfolders[:] = [d for d in subfolders
                         if os.path.relpath(os.path.join(directory, d), root) not in FOLDERS]
        for name in sorted(files):
            if not name.endswith(SOURCE_SUFFIXES):
                continue
            path = os.path.join(directory, name)
            with open(path, encoding="utf-8", errors="replace") as f:
                for number, line in enumerate(f, 1):
                    match = INCLUDE.match(line)
                    if not match:
                        continue
                    quoted, target = match.group(1) == '"', match.group(2)
                    where = f"{os.path.relpath(path, root)}:{number}"
                    if quoted:
                        used = owner(target)
                        if used and used not in folders:
                            errors.append(f"{where}: error: {folder}/ includes \"{target}\", but "
                                          f"its README does not allow {used}/")
                        elif (used and used != folder and public.get(used) is not None and
                              target[len(used) + 1:] not in public[used]):
                            errors.append(f"{where}: error: {folder}/ includes \"{target}\", "
                                          f"which is private to {used}/ (see its README's "
                                          f"'Public headers')")
                    else:
                        head = target.split("/")[0]
                        if head in GUARDED and head not in guarded:
                            errors.append(f"{where}: error: {folder}/ includes <{target}>, which "
                                          f"only folders whose README names <{head}/> may use")
    return errors


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=os.path.join(os.path.dirname(__file__), "..", ".."))
    args = parser.parse_args()
    root = os.path.abspath(args.root)
    present = [f for f in FOLDERS if os.path.isdir(os.path.join(root, f))]
    public = {f: public_headers_of(root, f) for f in present}
    errors = []
    for folder in present:
        errors += check_folder(root, folder, public)
    for error in errors:
        print(error)
    if errors:
        print(f"layering: {len(errors)} include(s) cross a dependency the READMEs do not allow")
        return 1
    print("layering: every include is allowed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
