#!/usr/bin/env bash
# The naga translations of the WGSL library (crates/microsurface-gpu/generated/, written by
# `cargo run -p microsurface-gpu --example translate`; tests/generated.rs checks they are
# current) validate in the Khronos tools (Debian's glslang-tools and spirv-tools):
#   GLSL 450: glslangValidator for OpenGL, and compiled for Vulkan (-V), then spirv-val;
#   SPIR-V: spirv-val;
#   HLSL (SM 6.0): each entry point compiled by glslang's HLSL front end (-D -V), then spirv-val.
# (MSL has no validator on Linux: Apple's metal compiler only.)
set -euo pipefail
cd "$(dirname "$0")/../crates/microsurface-gpu/generated"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
n=0
for f in glsl/*.comp; do
  glslangValidator "$f" >"$tmp/log" || { cat "$tmp/log"; echo "GLSL (OpenGL) FAILED: $f"; exit 1; }
  glslangValidator -V -o "$tmp/glsl.spv" "$f" >"$tmp/log" || { cat "$tmp/log"; echo "GLSL (Vulkan) FAILED: $f"; exit 1; }
  spirv-val "$tmp/glsl.spv" || { echo "spirv-val FAILED on glslang's SPIR-V of $f"; exit 1; }
  entry=$(basename "$f" .comp)
  glslangValidator -D -S comp -e "$entry" -V -o "$tmp/hlsl.spv" microsurface.hlsl >"$tmp/log" \
    || { cat "$tmp/log"; echo "HLSL FAILED: $entry"; exit 1; }
  spirv-val "$tmp/hlsl.spv" || { echo "spirv-val FAILED on glslang's SPIR-V of the HLSL $entry"; exit 1; }
  n=$((n + 1))
done
spirv-val microsurface.spv || { echo "spirv-val FAILED: microsurface.spv"; exit 1; }
echo "GPU shaders: $n GLSL and HLSL entry points and microsurface.spv validate"
