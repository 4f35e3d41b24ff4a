#!/usr/bin/env bash
# Install the LinuxCNC interpreter (/usr/bin/rs274, Debian package linuxcnc-uspace) used as a test oracle
# by tests/test_rs274_oracle.py and tests/support/rs274.py.
#
# Best effort only: this script never fails the CI run. When the package cannot be installed (not root,
# no apt-get, package not in the configured archives, network down...) it prints a notice and exits 0;
# the oracle tests then skip. Idempotent: nothing is done when /usr/bin/rs274 already exists.
#
# Environment:
#   POSTPROC_SKIP_ORACLE=1   do not try to install at all
#   ORACLE_APT_UPDATE=0      do not run `apt-get update` before installing (default: run it once)
#
# Note: linuxcnc-uspace drags in a large dependency set (GTK/Tk, Python bindings, and with recommends an RT
# kernel image), so recommends are not installed here. rs274 itself needs none of them.

set -u

notice() { echo "install-oracle: $*" >&2; }

if [ -x /usr/bin/rs274 ]; then
  notice "rs274 already present ($(command -v rs274 || echo /usr/bin/rs274)); nothing to do"
  exit 0
fi

if [ "${POSTPROC_SKIP_ORACLE:-0}" = "1" ]; then
  notice "POSTPROC_SKIP_ORACLE=1; not installing LinuxCNC, its oracle tests will skip"
  exit 0
fi

if [ "$(id -u 2>/dev/null || echo 1)" != "0" ]; then
  notice "not running as root; not installing linuxcnc-uspace, its oracle tests will skip"
  exit 0
fi

if ! command -v apt-get >/dev/null 2>&1; then
  notice "apt-get not found; not installing linuxcnc-uspace, its oracle tests will skip"
  exit 0
fi

export DEBIAN_FRONTEND=noninteractive

if [ "${ORACLE_APT_UPDATE:-1}" != "0" ]; then
  if ! timeout 600 apt-get update -qq >/dev/null 2>&1; then
    notice "apt-get update failed; trying to install from the existing package lists"
  fi
fi

if ! apt-cache show linuxcnc-uspace >/dev/null 2>&1; then
  notice "package linuxcnc-uspace is not available from the configured apt sources; oracle tests will skip"
  exit 0
fi

if timeout 1800 apt-get install -y -qq --no-install-recommends linuxcnc-uspace >/tmp/install-oracle.log 2>&1 \
   && [ -x /usr/bin/rs274 ]; then
  notice "installed linuxcnc-uspace $(dpkg-query -W -f='${Version}' linuxcnc-uspace 2>/dev/null)"
else
  notice "could not install linuxcnc-uspace (log: /tmp/install-oracle.log); oracle tests will skip"
  tail -n 5 /tmp/install-oracle.log >&2 2>/dev/null || true
fi
exit 0
