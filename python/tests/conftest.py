import os
import shutil
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))  # vectors.py


@pytest.fixture(scope="session")
def cli() -> str:
    """The command-line tool (ROBOWIRE_CLI, else robowire on PATH); skipped when neither exists."""
    path = os.environ.get("ROBOWIRE_CLI") or shutil.which("robowire")
    if not path or not os.path.exists(path):
        pytest.skip("the robowire command-line tool is not built (set ROBOWIRE_CLI)")
    return path
