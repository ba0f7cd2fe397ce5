"""The API reference (docs/reference, scripts/build_docs.sh) builds without a warning, and every
public function and class is in it, once, under the name users import it by."""

from __future__ import annotations

import pathlib
import subprocess
import sys

import pytest

pytest.importorskip("sphinx")
pytest.importorskip("numpydoc")

from sphinx.util.inventory import InventoryFile  # noqa: E402

from test_api_docs import OBJECTS  # noqa: E402

pytestmark = pytest.mark.text  # run once per CI, not under the sanitizers (conftest.py)

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.mark.slow
def test_the_reference_builds_without_warnings_and_documents_every_public_name(tmp_path):
    out = tmp_path / "html"
    done = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-n", "-q", "-b", "html",
                           str(ROOT / "docs" / "reference"), str(out)], capture_output=True, text=True,
                          cwd=tmp_path)
    assert done.returncode == 0, f"the reference does not build cleanly:\n{done.stderr[-6000:]}"
    with open(out / "objects.inv", "rb") as f:
        inventory = InventoryFile.load(f, "", lambda base, uri: uri)
    documented = {name for kind in ("py:class", "py:function", "py:exception", "py:method", "py:data")
                  for name in inventory.get(kind, {})}
    missing = [name for name, _ in OBJECTS if name not in documented]
    assert not missing, f"public names missing from the reference: {missing}"
