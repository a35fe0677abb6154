#!/usr/bin/env bash
# Runs brdf-gpu-equiv on the machine it was carried to (see prepare.sh): the carried Vulkan
# loader and GL dispatch libraries on LD_LIBRARY_PATH, the NVIDIA ICD named where one is
# installed, the figures written to $OUT (default gpu/device/out).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
lib="$here/root/usr/lib/x86_64-linux-gnu"
test -e "$lib/libvulkan.so.1" || { echo "no $lib/libvulkan.so.1: run prepare.sh first" >&2; exit 1; }
export LD_LIBRARY_PATH="$lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
if [ -z "${VK_ICD_FILENAMES:-}" ] && [ -z "${VK_DRIVER_FILES:-}" ]; then
  for dir in /usr/local/nvidia/share/vulkan/icd.d /usr/share/vulkan/icd.d /etc/vulkan/icd.d /usr/local/share/vulkan/icd.d; do
    if [ -f "$dir/nvidia_icd.json" ]; then
      # VK_DRIVER_FILES for loaders from 1.3.207 on, VK_ICD_FILENAMES for older ones.
      export VK_DRIVER_FILES="$dir/nvidia_icd.json" VK_ICD_FILENAMES="$dir/nvidia_icd.json"
      break
    fi
  done
fi
out="${OUT:-$here/out}"
mkdir -p "$out"
{
  echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "LD_LIBRARY_PATH=$LD_LIBRARY_PATH"
  echo "VK_DRIVER_FILES=${VK_DRIVER_FILES:-} VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-}"
  ls /usr/local/nvidia/share/vulkan/icd.d /usr/share/vulkan/icd.d /etc/vulkan/icd.d 2>/dev/null || true
  if command -v nvidia-smi >/dev/null; then
    nvidia-smi --query-gpu=name,driver_version --format=csv,noheader || true
  fi
  ldconfig -p 2>/dev/null | grep -E 'libGLX_nvidia|libnvidia-glcore|libvulkan' || true
  echo "glibc: $(ldd --version 2>/dev/null | head -1) (the binary needs 2.35 or newer)"
} | tee "$out/environment.txt"
set +e
"$here/bin/brdf-gpu-equiv" --out "$out" 2>&1 | tee "$out/run.log"
status=${PIPESTATUS[0]}
if [ "$status" = 2 ]; then
  # No adapter: once more with the loader's own diagnostics, for the next attempt.
  VK_LOADER_DEBUG=error,warn,driver "$here/bin/brdf-gpu-equiv" --out "$out" \
    > "$out/loader-debug.log" 2>&1
  tail -n 40 "$out/loader-debug.log"
fi
exit "$status"
