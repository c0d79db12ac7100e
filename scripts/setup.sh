# Sourced by demo.sh and test.sh: installs what is missing from Debian 12, configures and builds.
# pm_setup [release|sanitize]  ->  sets PM_BUILD_DIR to the built tree.

PM_DEBIAN_PACKAGES=(build-essential cmake ninja-build pkg-config libvisp-dev libopencv-dev libeigen3-dev
  libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev libcli11-dev libpng-dev libjpeg-dev libapriltag-dev)

pm_install_deps() {
  local missing=()
  for p in "${PM_DEBIAN_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "installing: ${missing[*]}" >&2
  if [ "$(id -u)" -ne 0 ]; then
    echo "error: missing Debian packages; run as root: apt-get install ${missing[*]}" >&2
    return 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq "${missing[@]}" >/dev/null
}

pm_setup() {
  local mode="${1:-release}" root
  root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  pm_install_deps
  case "$mode" in
    release)  PM_BUILD_DIR="$root/build";      set -- -DCMAKE_BUILD_TYPE=Release -DPM_SANITIZE=OFF ;;
    sanitize) PM_BUILD_DIR="$root/build-asan"; set -- -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPM_SANITIZE=ON ;;
    *) echo "error: unknown build mode '$mode' (release or sanitize)" >&2; return 2 ;;
  esac
  cmake -S "$root" -B "$PM_BUILD_DIR" -G Ninja "$@" >/dev/null
  cmake --build "$PM_BUILD_DIR" -j "$(nproc)"
  export PM_BUILD_DIR
}
