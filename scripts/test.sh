#!/usr/bin/env bash
# Runs every test of the solution. The serial integration tests need socat (Debian package) for
# pseudo-terminal pairs; install it when missing. A missing socat fails those tests, it never skips them.
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v socat >/dev/null 2>&1; then
  echo "test.sh: installing socat (needed for the real serial tests)"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq socat >/dev/null
fi

# A hung test host is killed and named after 3 minutes rather than holding CI until its limit.
dotnet test OperatorPanel.sln --nologo -v minimal --blame-hang-timeout 3m "$@"
