#!/usr/bin/env python3
"""Every endpoint of `gonio view` (viewer/api.h) against a running server: answers, error codes
with JSON messages, concurrent requests, paths outside the page, light files (cspec with 300 and
301 samples, curve; save, load, save byte-identical), exports, match; then a bad image and a
clean stop on SIGINT. Usage: http_test.py --gonio GONIO --image REFLECTANCE.exr"""

import argparse
import concurrent.futures
import json
import math
import os
import re
import signal
import socket
import struct
import subprocess
import sys
import tempfile
import urllib.error
import urllib.request

failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


def request(url, path, body=None, method=None, raw=False):
    """(status, headers, body): the body parsed as JSON unless raw."""
    data = body if isinstance(body, (bytes, type(None))) else (
        body.encode() if isinstance(body, str) else json.dumps(body).encode())
    req = urllib.request.Request(url + path, data=data, method=method)
    try:
        with urllib.request.urlopen(req, timeout=30) as response:
            status, headers, content = response.status, response.headers, response.read()
    except urllib.error.HTTPError as e:
        status, headers, content = e.code, e.headers, e.read()
    if raw:
        return status, headers, content
    return status, headers, json.loads(content) if content else None


def raw_get(port, target):
    """The status of a GET sent byte for byte (urllib would normalise ../)."""
    with socket.create_connection(("127.0.0.1", port), timeout=10) as s:
        s.sendall(f"GET {target} HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n".encode())
        reply = b""
        while chunk := s.recv(65536):
            reply += chunk
    status = int(reply.split(b" ", 2)[1])
    return status, reply.split(b"\r\n\r\n", 1)[1]


def start(gonio, image, *extra):
    process = subprocess.Popen([gonio, "view", image, "--port", "0", *extra],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    line = process.stdout.readline()
    found = re.match(r"gonio view: (http://127\.0\.0\.1:(\d+)/)", line)
    if not found:
        process.kill()
        raise SystemExit(f"no URL from gonio view: {line!r} {process.stderr.read()}")
    return process, found.group(1), int(found.group(2))


def floats(content):
    return struct.unpack(f"<{len(content) // 4}f", content)


def test_metadata_and_spectra(url):
    status, _, info = request(url, "api/image")
    check(status == 200 and info["width"] == 448 and info["height"] == 128, "GET /api/image: size")
    n = len(info["wavelengths"])
    check(n == 81 and info["wavelengths"][0] == 380 and info["wavelengths"][-1] == 780,
          "GET /api/image: 81 wavelengths 380-780 nm")
    for name in ("box", "cie"):
        m = info["toRgb"][name]
        check(len(m) == 3 and all(len(row) == n for row in m), f"toRgb.{name} is 3 x {n}")
    status, headers, content = request(url, "api/image/spectra", raw=True)
    check(status == 200 and len(content) == 448 * 128 * n * 4, "GET /api/image/spectra: w*h*n float32")
    samples = floats(content)
    # The centre of patch TCS01 (top row, first column): its reflectance, about 0.2-0.35.
    pixel = (32 * 448 + 32) * n
    check(0.1 < samples[pixel + 40] < 0.5, f"TCS01 at 580 nm is a reflectance: {samples[pixel + 40]}")
    check(info["basis"] is None, "GET /api/image: an image of samples has no basis")
    status, _, body = request(url, "api/image/coefficients")
    check(status == 400 and "not coefficients in a basis" in body["error"],
          "GET /api/image/coefficients of an image of samples: 400")
    return info


def test_illuminants(url, info):
    status, _, body = request(url, "api/illuminants")
    check(status == 200 and {"D65", "A", "E", "F11"} <= set(body["names"])
          and not any(n.startswith("TCS") for n in body["names"]), "GET /api/illuminants")
    status, _, f11 = request(url, "api/illuminants/F11")
    cie = info["toRgb"]["cie"]
    rgb = [sum(m * v for m, v in zip(row, f11["values"])) for row in cie]
    y = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]
    check(status == 200 and abs(y - 1) < 1e-9, f"F11 preset normalised to luminance 1: {y}")
    check(all(abs(v - r * f11["scale"]) < 1e-12 for v, r in zip(f11["values"], f11["raw"])),
          "F11 preset: values = raw * scale")
    status, _, body = request(url, "api/illuminants/TCS01")
    check(status == 400 and "no illuminant" in body["error"], "a reflectance is not a preset: 400")


def test_relight_and_errors(url, info):
    n = len(info["wavelengths"])
    light = [1.0] * n
    status, _, content = request(url, "api/relight", {"light": light, "conversion": "box"}, raw=True)
    rgb = floats(content)
    pixel = 3 * (32 * 448 + 32)
    check(status == 200 and len(rgb) == 3 * 448 * 128, "POST /api/relight: 3 float32 per pixel")
    _, _, spectra = request(url, "api/image/spectra", raw=True)
    samples = floats(spectra)[(32 * 448 + 32) * n:(32 * 448 + 33) * n]
    blue = sum(samples[:27]) / 27
    check(abs(rgb[pixel + 2] - blue) < 1e-6, "Box: blue is the mean of the first third")
    bad = [
        ("api/relight", {"light": [1.0] * (n - 1)}, "81 are needed"),
        ("api/relight", {"light": [1.0] * (n - 1) + [-1]}, "negative"),
        ("api/relight", {"light": ["x"] * n}, "must be a number"),
        ("api/relight", {"light": light, "conversion": "xyz"}, "unknown RGB conversion"),
        ("api/relight", "not json", "not JSON"),
        ("api/relight", "[1, 2]", "JSON object"),
        ("api/export", {"light": light, "format": "gif"}, "unknown image format"),
        ("api/difference", {"lightA": light}, "missing field \"lightB\""),
        ("api/match", {"light": light, "target": [1, 1]}, "3 are needed"),
        ("api/light/save", {"format": "cspec", "start": 380, "step": 1}, "missing field"),
        ("api/light/save", {"format": "spd"}, "unknown light format"),
        ("api/light/load", "cspec 400 410 5\n1\n2\n", "truncated"),
        ("api/light/load", "cspec 400 410 5\n1\n-2\n3\n", "negative"),
    ]
    for path, body, message in bad:
        status, _, answer = request(url, path, body)
        check(status == 400 and message in answer.get("error", ""),
              f"POST /{path} {str(body)[:40]!r}: 400 '{message}' ({answer})")
    status, _, answer = request(url, "api/nothing")
    check(status == 404 and "error" in answer, "GET an unknown endpoint: 404 with a message")
    status, _, answer = request(url, "api/image", b"{}", method="POST")
    check(400 <= status < 500 and "error" in answer, f"POST to a GET endpoint: {status}")
    status, _, answer = request(url, "api/relight", b"x" * (17 << 20))
    check(status == 413, f"a 17 MB body is refused: {status}")


def test_paths_outside_the_page(url, port):
    status, body = raw_get(port, "/")
    check(status == 200 and b"<canvas" in body, "GET / is the page")
    status, _, content = request(url, "main.mjs", raw=True)
    check(status == 200 and b"import" in content, "GET /main.mjs: an embedded file")
    for target in ("/../../../../etc/passwd", "/..%2f..%2fetc%2fpasswd", "/%2e%2e/%2e%2e/etc/passwd",
                   "/api/../../etc/passwd", "/web/index.html", "/CMakeLists.txt"):
        status, body = raw_get(port, target)
        check(status in (400, 404) and b"root:" not in body, f"GET {target}: {status}, nothing read")


def test_concurrent(url, info):
    n = len(info["wavelengths"])
    def relight(k):
        light = [1.0 + 0.01 * (k % 4)] * n
        return k % 4, request(url, "api/relight", {"light": light}, raw=True)
    with concurrent.futures.ThreadPoolExecutor(16) as pool:
        results = list(pool.map(relight, range(64)))
    check(all(status == 200 for _, (status, _, _) in results), "64 concurrent relights: all 200")
    by_light = {}
    for k, (_, _, content) in results:
        by_light.setdefault(k, set()).add(content)
    check(all(len(v) == 1 for v in by_light.values()) and len(by_light) == 4,
          "64 concurrent relights: the same light gives the same bytes, different ones differ")


def light_file(count):
    return "cspec 400 %d 1\n" % (400 + count - 1) + "".join(f"{0.5 + 0.001 * i}\n" for i in range(count))


def test_light_files(url, info):
    for count in (300, 301):
        status, _, light = request(url, "api/light/load?name=thesis.cspec", light_file(count))
        check(status == 200 and light["kind"] == "samples" and len(light["values"]) == count,
              f"a {count}-sample cspec loads")
        check(light["atImage"][0] == 0 and abs(light["atImage"][4] - 0.5) < 1e-12 and "note" in light,
              f"{count} samples: 0 outside 400-{399 + count} nm, said in a note")
    curve = "# fig. D.3\ncurve 5 400 700\n0.0 0.5\n0.0 0.5\n0.5 1.0\n1.0 0.25\n1.0 0.25\n"
    status, _, light = request(url, "api/light/load?name=d3.curve", curve)
    check(status == 200 and light["kind"] == "curve" and light["wavelengths"] == [400, 550, 700],
          "a curve file loads as control points")
    status, _, text = request(url, "api/light/save", {"format": "curve", "wavelengths": light["wavelengths"],
                                                      "values": light["values"], "before": light["before"],
                                                      "after": light["after"]}, raw=True)
    _, _, again = request(url, "api/light/load?name=saved.curve", text)
    _, _, text2 = request(url, "api/light/save", {"format": "curve", "wavelengths": again["wavelengths"],
                                                  "values": again["values"], "before": again["before"],
                                                  "after": again["after"]}, raw=True)
    check(status == 200 and text.startswith(b"# saved by gonio view\ncurve 5 400 700") and text == text2,
          "curve: save, load, save is byte-identical")
    values = [0.25 * (i % 7) for i in range(401)]
    _, _, text = request(url, "api/light/save", {"format": "cspec", "start": 380, "step": 1,
                                                 "values": values}, raw=True)
    _, _, again = request(url, "api/light/load?name=saved.cspec", text)
    _, _, text2 = request(url, "api/light/save", {"format": "cspec", "start": 380, "step": 1,
                                                  "values": again["values"]}, raw=True)
    check(text.count(b"\n") == 403 and again["values"] == values and text == text2,
          "cspec: save, load, save is byte-identical")


def test_export_match_difference(url, info):
    n = len(info["wavelengths"])
    light = [1.0] * n
    status, headers, png = request(url, "api/export", {"light": light, "format": "png"}, raw=True)
    check(status == 200 and png[:8] == b"\x89PNG\r\n\x1a\n" and headers["Content-Type"] == "image/png",
          "POST /api/export png")
    status, _, exr = request(url, "api/export", {"light": light, "format": "exr"}, raw=True)
    check(status == 200 and exr[:4] == b"\x76\x2f\x31\x01", "POST /api/export exr")
    _, _, d65 = request(url, "api/illuminants/D65")
    _, _, f11 = request(url, "api/illuminants/F11")
    status, _, match = request(url, "api/match", {"light": d65["values"], "target": [0.9, 0.6, 0.3],
                                                  "brightness": "none"})
    check(status == 200 and match["reachable"] and min(match["spectrum"]) >= 0, "POST /api/match: reachable, >= 0")
    check(max(abs(a - b) for a, b in zip(match["rgb"], [0.9, 0.6, 0.3])) < 1e-9
          and match["rgbResidual"] < 1e-9 and match["newtonSteps"] <= 10,
          f"POST /api/match: RGB = target ({match['rgb']}, {match['newtonSteps']} steps)")
    cie = info["toRgb"]["cie"]
    f11_rgb = [sum(m * v for m, v in zip(row, f11["values"])) for row in cie]
    _, _, metamer = request(url, "api/match", {"light": d65["values"], "target": f11_rgb})
    status, headers, content = request(url, "api/difference", {"lightA": f11["values"],
                                                               "lightB": metamer["spectrum"]}, raw=True)
    mean = float(headers["X-Mean-DeltaE"])
    check(status == 200 and len(content) == 4 * 448 * 128 and mean >= 3,
          f"POST /api/difference: F11 and D65 matched to it differ (mean ΔE2000 {mean:.2f})")
    _, headers, _ = request(url, "api/difference", {"lightA": f11["values"], "lightB": f11["values"]}, raw=True)
    check(float(headers["X-Max-DeltaE"]) == 0, "POST /api/difference of one light with itself: 0")


def test_bad_images(gonio, image):
    with tempfile.TemporaryDirectory() as folder:
        bad = os.path.join(folder, "bad.exr")
        with open(bad, "wb") as f:
            f.write(open(image, "rb").read()[:4000])  # truncated
        for path, why in ((bad, "error"), (os.path.join(folder, "none.exr"), "cannot open"),
                          (__file__, "error")):
            run = subprocess.run([gonio, "view", path], capture_output=True, text=True, timeout=30)
            check(run.returncode == 1 and path in run.stderr and why in run.stderr,
                  f"gonio view {os.path.basename(path)}: exit 1 naming the file ({run.stderr.strip()[:80]})")
    run = subprocess.run([gonio, "view", image, "--port", "70000"], capture_output=True, timeout=30)
    check(run.returncode == 2, "gonio view --port 70000: a usage error")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--gonio", required=True)
    parser.add_argument("--image", required=True)
    args = parser.parse_args()
    process, url, port = start(args.gonio, args.image)
    try:
        info = test_metadata_and_spectra(url)
        test_illuminants(url, info)
        test_relight_and_errors(url, info)
        test_paths_outside_the_page(url, port)
        test_concurrent(url, info)
        test_light_files(url, info)
        test_export_match_difference(url, info)
    finally:
        process.send_signal(signal.SIGINT)
        code = process.wait(timeout=10)
    check(code == 0 and "stopped (SIGINT)" in process.stdout.read(), "SIGINT stops it cleanly (exit 0)")
    test_bad_images(args.gonio, args.image)
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
