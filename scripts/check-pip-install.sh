#!/bin/sh
# README "Python": `pip install .` into a fresh venv, exactly as a user types it, then `import sgtllc`.
#   scripts/check-pip-install.sh PYTHON SOURCE_DIR
# Runs in a temporary folder (removed afterwards). Exit 77 (ctest's SKIP_RETURN_CODE) only if PYTHON cannot make
# a venv with pip (Debian: python3-venv missing; scripts/install-deps.sh installs it).
set -eu
PYTHON=$1
SOURCE=$2
if ! "$PYTHON" -c "import ensurepip, venv" 2>/dev/null; then
  echo "SKIP: $PYTHON has no venv/ensurepip (Debian: apt-get install python3-venv, or scripts/install-deps.sh)"
  exit 77
fi
TMP=$(mktemp -d "${TMPDIR:-/tmp}/sgtllc_pip.XXXXXX")
trap 'rm -rf "$TMP"' EXIT
cd "$TMP"
export PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_NO_CACHE_DIR=1
"$PYTHON" -m venv --system-site-packages v
v/bin/pip install --no-build-isolation "$SOURCE"
# Imported from the venv (not the source tree), and the stub installed beside it.
cd /
"$TMP"/v/bin/python -c "import sgtllc, os, sys; \
assert sgtllc.__file__.startswith(sys.prefix), sgtllc.__file__; \
assert os.path.exists(os.path.join(os.path.dirname(sgtllc.__file__), 'sgtllc.pyi')); \
print('pip-install: imported', sgtllc.__file__, 'version', sgtllc.__version__)"
