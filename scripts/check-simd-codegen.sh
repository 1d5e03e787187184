#!/usr/bin/env bash
# The AVX-512 (and AVX2) builds of fast::batch's slice functions must load and store their
# contiguous slices with plain vector moves: no scatters anywhere, and no gathers in the
# closed-form kernels (GGX D, Λ, G1; Beckmann D), which read nothing but the slices. (Gathers
# of table rows in the fitted kernels are lookups, and stay.) An AVX-512 build that vectorised
# across 8-element chunks with 16 gathers and 8 scatters per iteration was 5–13× slower than
# its AVX2 build on AMD Zen 5 (issue 19); this check needs no AVX-512 CPU.
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_TARGET_DIR=target/codegen-check
cargo rustc --release --quiet -p microsurface --lib -- --emit asm -C codegen-units=1
asm=$(ls -t "$CARGO_TARGET_DIR"/release/deps/microsurface-*.s | head -n 1)
report=$(awk '
  /^_ZN12microsurface4fast5batch[0-9]+[a-z_0-9]+[0-9]+(avx512|avx2)/ { fn = $0; next }
  /^_ZN/ { fn = "" }
  fn != "" && /vscatter/ { print "scatter in " fn }
  fn ~ /batch(5ggx_d|10ggx_lambda|6ggx_g1|10beckmann_d)[0-9]/ && /vgather/ { print "gather in " fn }
' "$asm" | sort | uniq -c)
if [ -n "$report" ]; then
  echo "SIMD codegen check FAILED ($asm):"
  echo "$report"
  exit 1
fi
n=$(grep -c '^_ZN12microsurface4fast5batch.*avx512' "$asm")
echo "SIMD codegen check: $n AVX-512 slice functions, no scatters, no gathers in the closed-form kernels"
