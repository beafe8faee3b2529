#!/usr/bin/env python3
"""Runs the shared conformance runner with our renderer and fails unless every scene passes.

  run_conformance.py RUNNER GONIO [runner options...]
"""
import re
import subprocess
import sys

runner, gonio, *rest = sys.argv[1:]
result = subprocess.run([runner, '--render', f'{gonio} render {{rib}}', *rest],
                        capture_output=True, text=True)
sys.stdout.write(result.stdout)
sys.stderr.write(result.stderr)
summary = re.search(r'(\d+) passed, (\d+) failed', result.stdout)
if result.returncode != 0 or not summary:
    sys.exit('conformance runner did not finish')
sys.exit(1 if int(summary.group(2)) > 0 else 0)
