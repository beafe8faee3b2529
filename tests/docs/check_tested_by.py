#!/usr/bin/env python3
"""Checks the "tested by" column of the docs' tables against the repository: every reference
must name a test that exists and that ctest runs, and no cell may be "?" (a row nobody has
looked at). Meant to run as a ctest, e.g.

    check_tested_by.py docs/rib-support.md docs/shading-language.md --root .

A cell is "—" (nothing tests the row: a known gap, allowed) or references separated by ";",
each `PREFIX: ITEM[, ITEM...]`:

* PREFIX is a ctest name (`add_test(NAME render_golden ...)` in some CMakeLists.txt), a
  GoogleTest executable given to gtest_discover_tests (`rib_tests`), or the stem of a test
  source that one of those runs (`rib_requests_test` for tests/rib/rib_requests_test.cpp);
* ITEM is a GoogleTest `Suite.Name` (a TEST, TEST_F or TEST_P in those sources), a check
  function (`def name(` in the ctest's script, registered with @check, listed in its CHECKS or
  called), a case of a CASES table (`("name", ...`), a label of a shell test (`expect name`),
  or a file or folder the ctest reads (a golden scene `quadric_sphere.rib` under the ctest's
  folder, a conformance scene under the folder its command names).

A check registered with known_bug= (not run by ctest) or of another --group than the ctest
runs is an error too. A reference into a folder outside the repository that does not exist
here (../shared/conformance) is a warning: ctest does not run that test there either.
Prints each problem as DOC:LINE: and exits 1 when there is one."""

import argparse
import ast
import glob
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from add_tested_by import (COLUMN, DEFAULT_HEADERS, MISSING, find_tables, first_cell,  # noqa: E402
                           orphan_message, orphan_runs, split_cells)

GAP = ("—", "–", "-")
FILE_ITEM = re.compile(r"^[\w.+-]+\.(rib|rib\.gz|sl|h|tif|tiff|png|exr|grd|pm|txt|json|py|sh|mjs)$")
TEST_ITEM = re.compile(r"^(?:\w+/)?([A-Za-z_]\w*)\.([A-Za-z_]\w*)(?:/\w+)?$")
SKIP_DIRS = {".git", "node_modules", "__pycache__"}


# ---- the build's tests ------------------------------------------------------------------------

def cmake_commands(text):
    """(name, [arguments]) of each command in a CMakeLists.txt, comments dropped, quotes kept
    off the arguments."""
    text = re.sub(r'("(?:[^"\\]|\\.)*")|#[^\n]*', lambda m: m.group(1) or "", text)
    for m in re.finditer(r"\b(\w+)\s*\(", text):
        depth, i = 1, m.end()
        while i < len(text) and depth:
            depth += {"(": 1, ")": -1}.get(text[i], 0)
            i += 1
        body = text[m.end():i - 1]
        args = [a[1:-1] if a.startswith('"') else a
                for a in re.findall(r'"(?:[^"\\]|\\.)*"|[^\s()]+', body)]
        yield m.group(1).lower(), args


class Tests:
    """What the CMakeLists.txt files under the root define: ctest names, GoogleTest
    executables and the sources and folders behind them."""

    def __init__(self, root):
        self.root = os.path.abspath(root)
        self.executables = {}  # target -> [source paths]
        self.ctests = {}       # ctest name -> (files, folders it reads, its --group or None)
        self.discovered = {}   # executable given to gtest_discover_tests -> [source paths]
        self.variables = {}    # folder -> {variable: value} of its CMakeLists.txt
        lists = []
        for folder, dirs, files in os.walk(self.root):
            dirs[:] = [d for d in dirs if not skipped(folder, d)]
            if "CMakeLists.txt" in files:
                lists.append((folder, list(cmake_commands(read(os.path.join(folder,
                                                                            "CMakeLists.txt"))))))
        for folder, commands in lists:
            self.read_targets(folder, commands)
        for folder, commands in lists:
            self.read_tests(folder, commands)
        self.stems = {}  # stem of a test source -> [(path, folders)]
        owners = list(self.ctests.values())
        owners += [(files, [os.path.dirname(p) for p in files], None)
                   for files in self.discovered.values()]
        tests_folder = os.path.join(self.root, "tests") + os.sep
        for files, dirs, _ in owners:
            for path in files:
                if path.startswith(tests_folder):  # not the sources of the program under test
                    stem = os.path.basename(path).split(".")[0]
                    self.stems.setdefault(stem, []).append((path, dirs))

    def expand(self, folder, value, variables):
        value = value.replace("${CMAKE_CURRENT_SOURCE_DIR}", folder)
        for name in ("PROJECT_SOURCE_DIR", "CMAKE_SOURCE_DIR"):
            value = value.replace("${%s}" % name, self.root)
        return re.sub(r"\$\{(\w+)\}", lambda m: variables.get(m.group(1), m.group(0)), value)

    def read_targets(self, folder, commands):
        """The variables (set, file(GLOB)) and executables of one CMakeLists.txt."""
        variables = self.variables.setdefault(folder, {})
        for name, args in commands:
            if name == "set" and len(args) >= 2:
                variables[args[0]] = self.expand(folder, " ".join(args[1:]), variables)
            elif name == "file" and len(args) > 1 and args[0] == "GLOB":
                found = []
                for a in args[2:]:
                    if a not in ("CONFIGURE_DEPENDS", "LIST_DIRECTORIES", "true", "false"):
                        found += sorted(glob.glob(os.path.join(folder,
                                                               self.expand(folder, a, variables))))
                variables[args[1]] = " ".join(found)
            elif name == "add_executable" and args:
                paths = [os.path.join(folder, part) for a in args[1:]
                         for part in self.expand(folder, a, variables).split()]
                self.executables[args[0]] = [os.path.normpath(p) for p in paths
                                             if os.path.isfile(p)]

    def read_tests(self, folder, commands):
        """The ctests and discovered GoogleTest executables of one CMakeLists.txt; an add_test
        inside foreach() is read once per value."""
        loops = []  # the foreach() blocks open around the command: (variable, values)
        for name, args in commands:
            if name == "foreach" and args:
                loops.append((args[0], args[1:]))
            elif name == "endforeach" and loops:
                loops.pop()
            elif name == "gtest_discover_tests" and args:
                self.discovered[args[0]] = self.executables.get(args[0], [])
            elif name == "add_test" and len(args) > 3 and args[0] == "NAME" and "COMMAND" in args:
                variable, values = loops[-1] if loops else (None, [None])
                for value in values:
                    self.add_ctest(folder, [a.replace("${%s}" % variable, value) if variable
                                            else a for a in args])

    def add_ctest(self, folder, args):
        command = [self.expand(folder, a, self.variables[folder])
                   for a in args[args.index("COMMAND") + 1:]]
        if "WORKING_DIRECTORY" in command:
            command = command[:command.index("WORKING_DIRECTORY")]
        # A script's test is the script; a binary's, the sources of its executable.
        files = [os.path.normpath(a) for a in command
                 if os.path.isfile(a) and a.endswith((".py", ".sh", ".mjs"))]
        for a in command if not files else []:
            target = re.sub(r"^\$<TARGET_FILE:(\w+)>$", r"\1", a)
            if target in self.executables:
                files = self.executables[target]
                break
        # The folders it reads: its own, and those its command names (../shared/conformance).
        dirs = [folder]
        for a in filter(os.path.isabs, command):
            path = os.path.normpath(a)
            if not path.startswith(self.root + os.sep) and path != self.root:
                dirs.append(path if os.path.isdir(path) else os.path.dirname(path))
            elif os.path.isdir(path):
                dirs.append(path)
        group = command[command.index("--group") + 1] if "--group" in command[:-1] else None
        self.ctests[args[1]] = (files, dirs, group)

    def resolve(self, prefix):
        """[(files, folders, group)] that `prefix` may mean, or []."""
        if prefix in self.ctests:
            return [self.ctests[prefix]]
        if prefix in self.discovered:
            files = self.discovered[prefix]
            return [(files, sorted({os.path.dirname(p) for p in files}), None)]
        return [([path], dirs, None) for path, dirs in self.stems.get(prefix, [])]


def skipped(folder, name):
    """Folders not searched: version control, caches and build trees."""
    return name in SKIP_DIRS or os.path.exists(os.path.join(folder, name, "CMakeCache.txt"))


# ---- one reference ----------------------------------------------------------------------------

def read(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        return f.read()


def find_named(dirs, item, root):
    """Whether a file or folder named `item` (or `item.*`) lies under one of `dirs`. Returns
    True, False, or None when every outside folder it could be in is missing."""
    missing_outside = False
    for d in dirs:
        if not os.path.isdir(d):
            missing_outside |= not d.startswith(root)
            continue
        for folder, subdirs, files in os.walk(d):
            subdirs[:] = [s for s in subdirs if not skipped(folder, s)]
            names = files + subdirs
            if item in names or any(n.split(".")[0] == item for n in names):
                return True
    return None if missing_outside else False


def check_function(path, text, item, group):
    """None when `def item(` in the script is a check ctest runs, "missing" when there is no
    such function, else why ctest does not run it."""
    m = re.search(r"((?:^@.*\n)*)^def %s\(" % re.escape(item), text, re.M)
    if not m:
        return "missing"
    decorators = m.group(1)
    if not decorators and len(re.findall(r"\b%s\b" % re.escape(item), text)) < 2:
        return f"{item}() in {path} is never registered or called"
    if "known_bug" in decorators:
        return f"{item}() is marked known_bug= in {path}: ctest does not run it"
    registered = re.search(r'@check\(\s*"(\w+)"', decorators)
    if group and registered:
        # analytic_checks.py: a batch group runs with the --group BATCH_GROUPS maps it to.
        groups = re.search(r"^BATCH_GROUPS\s*=\s*(\{.*?\})", text, re.M | re.S)
        own = registered.group(1)
        runs_in = ast.literal_eval(groups.group(1)).get(own, own) if groups else own
        if runs_in != group:
            return f'{item}() is in group "{own}" ({runs_in}); this ctest runs --group {group}'
    return None


def in_scripts(texts, item, group, root):
    """(found, [why not]) for a check function, CASES entry or shell label `item`."""
    reasons = []
    for path, text in texts.items():
        if path.endswith(".py"):
            why = check_function(os.path.relpath(path, root), text, item, group)
            if why is None:
                return True, []
            if why != "missing":
                reasons.append(why)
            elif re.search(r'^\s*\(\s*"%s"\s*,' % re.escape(item), text, re.M):
                return True, []
        elif path.endswith(".sh") and re.search(r"(?<![\w-])%s(?![\w-])" % re.escape(item),
                                                text):
            return True, []
    return False, reasons


def check_candidate(files, dirs, group, item, root):
    """(found, unsure, [why not]) for `item` in one meaning of a prefix; unsure when it may lie
    in an outside folder that is missing here."""
    texts = {p: read(p) for p in files if os.path.isfile(p)}
    names = ", ".join(os.path.relpath(p, root) for p in texts) or "its sources"
    test = TEST_ITEM.match(item)
    if test and not FILE_ITEM.match(item):
        pattern = re.compile(r"\bTEST(?:_F|_P)?\(\s*%s\s*,\s*%s\s*\)" % test.groups())
        found = any(pattern.search(t) for t in texts.values())
        return found, False, [f"no TEST({test.group(1)}, {test.group(2)}) in {names}"]
    if FILE_ITEM.match(item):
        found = find_named(dirs + [os.path.dirname(p) for p in files], item, root)
        return bool(found), found is None, [f"no file {item} where it reads its files"]
    found, reasons = in_scripts(texts, item, group, root)
    if found:
        return True, False, []
    if reasons:  # a check that exists but does not run: a file of that name would not help
        return False, False, reasons
    found = find_named(dirs, item, root)
    return bool(found), found is None, [f"no check, case or file named {item} in {names}"]


def check_item(candidates, item, root):
    """(None, None) when some candidate (files, folders, group) has `item`; else ("warning",
    why) when it may lie in an outside folder missing here, or ("error", why)."""
    reasons, unsure = [], False
    for files, dirs, group in candidates:
        found, maybe, why = check_candidate(files, dirs, group, item, root)
        if found:
            return None, None
        unsure |= maybe
        reasons += why
    why = "; ".join(dict.fromkeys(reasons))
    return ("warning", why + " (its folder is missing here)") if unsure else ("error", why)


def references(cell):
    """[(prefix, item)] of a cell; a malformed reference comes as (None, its text)."""
    out = []
    for ref in cell.replace("`", "").split(";"):
        ref = ref.strip()
        if not ref:
            continue
        prefix, _, items = ref.partition(":")
        items = [item.strip() for item in items.split(",")]
        if not prefix.strip() or not all(items):
            out.append((None, ref))
        else:
            out += [(prefix.strip(), item) for item in items]
    return out


# ---- the docs ---------------------------------------------------------------------------------

def check_cell(where, cell, tests, root, counts):
    """(errors, warnings) of one "tested by" cell."""
    errors, warnings = [], []
    if cell in ("", MISSING):
        return [f"{where}: no '{COLUMN}' entry ('{cell or 'empty'}')"], []
    if cell in GAP:
        counts["gaps"] += 1
        return [], []
    for prefix, item in references(cell):
        counts["refs"] += 1
        if prefix is None:
            errors.append(f"{where}: '{item}' is not 'PREFIX: ITEM[, ITEM...]'")
            continue
        candidates = tests.resolve(prefix)
        if not candidates:
            errors.append(f"{where}: '{prefix}: {item}': no ctest, GoogleTest executable or "
                          f"test source named '{prefix}'")
            continue
        level, why = check_item(candidates, item, root)
        if level:
            (warnings if level == "warning" else errors).append(f"{where}: '{prefix}: {item}': "
                                                                f"{why}")
    return errors, warnings


def check_doc(doc, tests, root, gaps):
    """Returns (errors, warnings, counts) for one doc; with `gaps`, prints the rows marked —."""
    errors, warnings = [], []
    counts = {"rows": 0, "refs": 0, "gaps": 0}
    lines = read(doc).split("\n")
    with_column = 0
    for header, _, rows in find_tables(lines):
        cells, _ = split_cells(lines[header])
        names = [c.strip().lower() for c in cells]
        if COLUMN not in names:
            if names[0] in DEFAULT_HEADERS:
                errors.append(f"{doc}:{header + 1}: the table of '{cells[0].strip()}' has no "
                              f"'{COLUMN}' column")
            continue
        with_column += 1
        index = names.index(COLUMN)
        for r in rows:
            counts["rows"] += 1
            row_cells, _ = split_cells(lines[r])
            cell = row_cells[index].strip() if index < len(row_cells) else ""
            where = f"{doc}:{r + 1}: {first_cell(lines[r])}"
            if gaps and cell in GAP:
                print(f"{where}: not tested ({cell})")
            e, w = check_cell(where, cell, tests, root, counts)
            errors += e
            warnings += w
    errors += [f"{doc}:{orphan_message(first, last)}" for first, last in orphan_runs(lines)]
    if not with_column:
        errors.append(f"{doc}: no table has a '{COLUMN}' column")
    return errors, warnings, counts


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("docs", nargs="+", metavar="DOC")
    parser.add_argument("--root", default=".", help="the repository (default: .)")
    parser.add_argument("--gaps", action="store_true", help="also list the rows marked —")
    args = parser.parse_args()
    root = os.path.abspath(args.root)
    tests = Tests(root)
    failed = False
    for doc in args.docs:
        errors, warnings, counts = check_doc(doc, tests, root, args.gaps)
        for w in warnings:
            print(f"{w} [warning]")
        for e in errors:
            print(e)
        failed |= bool(errors)
        print(f"{doc}: {counts['rows']} rows, {counts['refs']} references, "
              f"{counts['gaps']} untested (—), {len(errors)} problems")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
