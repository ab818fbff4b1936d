"""The example of docs/python.md runs, and the page shows it as it is."""
import os
import re
import subprocess
import sys

import numpy as np
import pytest

from conftest import SOURCE

pytest.importorskip("matplotlib")
EXAMPLE = SOURCE / "docs" / "python_example.py"


def test_the_page_shows_the_script_verbatim():
    page = (SOURCE / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", page, re.S)
    assert EXAMPLE.read_text() in blocks


def test_the_example_runs_and_draws_its_figure(tmp_path):
    r = subprocess.run([sys.executable, EXAMPLE, tmp_path], cwd=SOURCE, capture_output=True,
                       text=True, env=os.environ)
    assert r.returncode == 0, r.stderr
    figure = tmp_path / "python_example.png"
    assert figure.exists()
    import matplotlib.image

    pixels = matplotlib.image.imread(figure)
    assert pixels.shape[1] > 1000 and pixels[..., :3].std() > 0.05
