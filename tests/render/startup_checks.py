#!/usr/bin/env python3
"""Checks that gonio loads OpenImageIO only when a scene needs it, and the viewer's HTTP server
(cpp-httplib, OpenSSL) only for `gonio view` (issue 21): the executable does not link it; a
render without textures writing TIFF, PNG and OpenEXR never loads it (the dynamic loader's own
record, LD_DEBUG=files, of every object the process opened, dlopen included); OpenEXR is
loaded only to write an OpenEXR file; an empty frame does not start oneTBB; a textured scene loads the plugin and renders the texture's colour; and
without the plugin, what needed it says so while the built-in formats still work.

    startup_checks.py --gonio build/bin/gonio"""

import os
import subprocess
import sys

from analytic_checks import workspace_main, expect, read_images

SCENE = """Format 8 6 1
PixelSamples 1 1
PixelFilter "box" 1 1
Quantize "rgba" 0 0 0 0
{displays}
Projection "orthographic"
Translate 0 0 5
WorldBegin
Surface "{surface}"
Polygon "P" [-3 -3 0  3 -3 0  3 3 0  -3 3 0]
WorldEnd
"""

SHADERS = {
    "flat.sl": "surface flat() { Ci = color(0.25, 0.5, 0.75); Oi = 1; }",
    "textured.sl": 'surface textured() { Ci = color texture("tex.tif", 0.5, 0.5); Oi = 1; }',
}

BUILT_IN = ('Display "out.tif" "tiff" "rgba"\nDisplay "+out.png" "png" "rgb"\n'
            'Display "+out.exr" "openexr" "rgba"')


def render_traced(ws, rib, name, env=None):
    """Renders `rib`; returns the process and the shared objects the loader opened."""
    scene = ws.path(name + ".rib")
    with open(scene, "w") as f:
        f.write(rib)
    environment = dict(os.environ, LD_DEBUG="files", **(env or {}))
    proc = subprocess.run([ws.gonio, "render", scene], cwd=ws.dir, capture_output=True,
                          text=True, env=environment)
    loaded = [line.split("file=")[1].split()[0] for line in proc.stderr.splitlines()
              if "file=" in line]
    return proc, loaded


def uses_oiio(loaded):
    return [name for name in loaded if "OpenImageIO" in name or "gonio_oiio" in name]


def check_executable_does_not_link_oiio(ws):
    libraries = subprocess.run(["ldd", ws.gonio], capture_output=True, text=True).stdout
    expect("OpenImageIO" not in libraries, f"gonio links OpenImageIO:\n{libraries}")


def check_only_view_loads_the_http_server(ws):
    """cpp-httplib (and with it OpenSSL) is the viewer plugin's, opened by `gonio view` only: the
    executable does not link it, and a render does not load it."""
    libraries = subprocess.run(["ldd", ws.gonio], capture_output=True, text=True).stdout
    expect("httplib" not in libraries and "libssl" not in libraries,
           f"gonio links cpp-httplib or OpenSSL:\n{libraries}")
    proc, loaded = render_traced(ws, SCENE.format(displays=BUILT_IN, surface="flat"), "plain")
    expect(proc.returncode == 0, f"the render failed:\n{proc.stderr[-2000:]}")
    http = [name for name in loaded if "httplib" in name or "libssl" in name or "gonio_viewer"
            in name]
    expect(not http, f"a render loaded {http}")


def check_render_without_textures_loads_no_oiio(ws):
    proc, loaded = render_traced(ws, SCENE.format(displays=BUILT_IN, surface="flat"), "flat")
    expect(proc.returncode == 0, f"the render failed:\n{proc.stderr[-2000:]}")
    expect(len(loaded) > 3, f"LD_DEBUG=files recorded only {loaded}: the check would see nothing")
    expect(not uses_oiio(loaded), f"a render without textures loaded {uses_oiio(loaded)}")
    for image in read_images(ws.path("out.tif"), ws.path("out.png"), ws.path("out.exr")):
        got = image.pixels[(4, 3)][:3]
        expect(all(abs(a - b) < 0.5 / 255 for a, b in zip(got, (0.25, 0.5, 0.75))),
               f"pixel (4, 3) is {got}, expected 0.25 0.5 0.75")


def check_only_openexr_files_load_openexr(ws):
    """OpenEXR's libraries are the plugin libgonio_exr.so's: the executable does not link them, a
    render writing TIFF and PNG does not load them, one writing OpenEXR loads the plugin, and
    without the plugin an OpenEXR display fails with a located error while TIFF still works."""
    libraries = subprocess.run(["ldd", ws.gonio], capture_output=True, text=True).stdout
    expect("OpenEXR" not in libraries and "libIex" not in libraries,
           f"gonio links OpenEXR:\n{libraries}")
    tiff_png = 'Display "a.tif" "tiff" "rgba"\nDisplay "+a.png" "png" "rgb"'
    proc, loaded = render_traced(ws, SCENE.format(displays=tiff_png, surface="flat"), "tiffpng")
    expect(proc.returncode == 0, f"the render failed:\n{proc.stderr[-2000:]}")
    exr = [name for name in loaded if "OpenEXR" in name or "gonio_exr" in name]
    expect(not exr, f"a TIFF and PNG render loaded {exr}")
    rib = SCENE.format(displays='Display "a.exr" "openexr" "rgba"', surface="flat")
    proc, loaded = render_traced(ws, rib, "exr")
    expect(proc.returncode == 0 and any("gonio_exr" in name for name in loaded),
           f"an OpenEXR render (exit {proc.returncode}) did not load the plugin: {loaded}")
    missing = {"GONIO_EXR_PLUGIN": ws.path("no/libgonio_exr.so")}
    proc, _ = render_traced(ws, SCENE.format(displays=BUILT_IN, surface="flat"), "noexr", missing)
    errors = [line for line in proc.stderr.splitlines() if "error:" in line]
    expect(proc.returncode != 0 and any("libgonio_exr.so" in e and ".rib:" in e for e in errors),
           f"an OpenEXR display without the plugin: exit {proc.returncode}, errors {errors}")
    (image,) = read_images(ws.path("out.tif"))
    expect(abs(image.pixels[(4, 3)][0] - 0.25) < 0.5 / 255, "the TIFF beside it was not written")


def check_empty_frame_starts_no_tbb(ws):
    """An empty 1x1 frame (the start-up benchmark's) makes no Embree device and renders its one
    tile on the main thread, so oneTBB never opens libtbbmalloc (its first task, a scene commit
    or a thread-local table would); the pixel is empty, as every ray misses."""
    rib = 'Format 1 1 1\nDisplay "empty.tif" "tiff" "rgba"\nWorldBegin\nWorldEnd\n'
    proc, loaded = render_traced(ws, rib, "empty")
    expect(proc.returncode == 0, f"the render failed:\n{proc.stderr[-2000:]}")
    expect(any("libtbb.so" in name for name in loaded),
           f"LD_DEBUG=files did not record libtbb itself: the check would see nothing: {loaded}")
    tbbmalloc = [name for name in loaded if "tbbmalloc" in name]
    expect(not tbbmalloc, f"an empty frame loaded {tbbmalloc}")
    (image,) = read_images(ws.path("empty.tif"))
    expect(image.pixels[(0, 0)] == [0, 0, 0, 0], f"the empty pixel is {image.pixels[(0, 0)]}")


def check_texture_loads_the_plugin(ws):
    subprocess.run(["oiiotool", "--pattern", "constant:color=0.125,0.25,0.625", "16x16", "3",
                    "-d", "float", "-o", ws.path("tex.tif")], check=True, capture_output=True)
    rib = SCENE.format(displays='Display "tex_out.tif" "tiff" "rgba"', surface="textured")
    proc, loaded = render_traced(ws, rib, "textured")
    expect(proc.returncode == 0, f"the render failed:\n{proc.stderr[-2000:]}")
    expect(any("gonio_oiio" in name for name in loaded),
           f"a textured scene did not load the plugin: {loaded}")
    (image,) = read_images(ws.path("tex_out.tif"))
    got = image.pixels[(4, 3)][:3]
    expect(all(abs(a - b) < 1e-5 for a, b in zip(got, (0.125, 0.25, 0.625))),
           f"pixel (4, 3) is {got}, expected the texture's 0.125 0.25 0.625")


def check_missing_plugin_is_a_clear_error(ws):
    missing = {"GONIO_OIIO_PLUGIN": ws.path("no/libgonio_oiio.so")}
    proc, _ = render_traced(ws, SCENE.format(displays=BUILT_IN, surface="flat"), "noplugin",
                            missing)
    expect(proc.returncode == 0, f"built-in formats need no plugin, yet:\n{proc.stderr[-2000:]}")
    rib = SCENE.format(displays='Display "photo.jpg" "file" "rgb"', surface="flat")
    proc, _ = render_traced(ws, rib, "jpeg", missing)
    errors = [line for line in proc.stderr.splitlines() if "error:" in line]
    expect(proc.returncode != 0 and any("photo.jpg" in e and "OpenImageIO" in e for e in errors),
           f"writing a JPEG without the plugin: exit {proc.returncode}, errors {errors}")
    rib = SCENE.format(displays='Display "t.tif" "tiff" "rgba"', surface="textured")
    proc, _ = render_traced(ws, rib, "texnoplugin", missing)
    warnings = [line for line in proc.stderr.splitlines() if "warning:" in line]
    expect(any("tex.tif" in w and "OpenImageIO" in w for w in warnings),
           f"a texture without the plugin: warnings {warnings}")


CHECKS = [check_executable_does_not_link_oiio, check_only_view_loads_the_http_server,
          check_render_without_textures_loads_no_oiio, check_only_openexr_files_load_openexr,
          check_empty_frame_starts_no_tbb,
          check_texture_loads_the_plugin, check_missing_plugin_is_a_clear_error]


def main():
    return workspace_main(__doc__.split("\n\n")[0], CHECKS, "gonio_startup_", SHADERS)


if __name__ == "__main__":
    sys.exit(main())
