"""Shared helpers of the Python package's tests."""

import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def root() -> Path:
    """The repository root (scenes in models/)."""
    return ROOT


@pytest.fixture
def cli() -> Path:
    """The `adit` command built by `cargo test --workspace --release` (or `cargo build --release`):
    required when ADIT_REQUIRE_CLI=1 (as in .ci/run), else the test is skipped without it."""
    path = Path(os.environ.get("ADIT_BIN", ROOT / "target" / "release" / "adit"))
    if not path.exists():
        if os.environ.get("ADIT_REQUIRE_CLI") == "1":
            pytest.fail(f"ADIT_REQUIRE_CLI=1 but {path} does not exist")
        pytest.skip(f"{path} not built: cargo build --release")
    return path
