#!/usr/bin/env bash
# Prepares what brdf-gpu-equiv needs on a machine that has a GPU driver's Vulkan ICD but no
# Vulkan loader and no Rust toolchain: Debian's loader (libvulkan1) and the GL vendor-neutral
# dispatch libraries an NVIDIA ICD links against, fetched with apt-get download into debs/ and
# unpacked with dpkg -x into root/, and the release binary copied into bin/. All three folders
# are ignored by git (.git/info/exclude). Run on the build machine:
#   CARGO_TARGET_DIR=... cargo build --release -p brdf-gpu --bin brdf-gpu-equiv
#   gpu/device/prepare.sh [path/to/brdf-gpu-equiv]
# then carry gpu/device/ (run.sh, root/, bin/) and run gpu/device/run.sh there.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
bin="${1:-${CARGO_TARGET_DIR:-$repo/target}/release/brdf-gpu-equiv}"
test -x "$bin" || { echo "no binary at $bin: build it with cargo build --release -p brdf-gpu --bin brdf-gpu-equiv" >&2; exit 1; }
rm -rf "$here/debs" "$here/root" "$here/bin"
mkdir -p "$here/debs" "$here/root" "$here/bin"
(cd "$here/debs" && apt-get download libvulkan1 libglvnd0 libegl1 libgl1 libglx0 libopengl0 libgles2)
for deb in "$here"/debs/*.deb; do
  dpkg -x "$deb" "$here/root"
done
cp "$bin" "$here/bin/brdf-gpu-equiv"
echo "prepared: $(ls "$here/debs" | wc -l) packages unpacked into $here/root, binary in $here/bin"
ls "$here/root/usr/lib/x86_64-linux-gnu"
