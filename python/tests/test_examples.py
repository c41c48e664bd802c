"""examples/python/fig3.py runs and writes a PNG."""

import os
import subprocess
import sys

EXAMPLE = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "python", "fig3.py")
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def test_fig3_writes_a_png(tmp_path):
    png = tmp_path / "fig3.png"
    r = subprocess.run([sys.executable, EXAMPLE, str(png), "--points", "721"],
                       capture_output=True, text=True, timeout=300, check=False)
    assert r.returncode == 0, r.stderr
    assert r.stdout == f"written: {png}\n"
    assert png.read_bytes()[:8] == PNG_SIGNATURE and png.stat().st_size > 10_000
