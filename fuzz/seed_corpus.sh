#!/usr/bin/env bash
# Assembles the seed corpus of every fuzzer in OUT_DIR/<fuzzer>/ from data/ (valid inputs)
# and data/bad/ (the reproducers of past reader bugs, so that every run replays them), plus
# fuzz/findings/. OBJ, PLY and STL seeds are converted from the OFF meshes of data/, since
# data/ holds none of them; the binary PLY and STL seeds are one triangle, written bytewise.
# Files already in OUT_DIR are kept: a local corpus keeps growing from run to run.
# usage: fuzz/seed_corpus.sh OUT_DIR
set -euo pipefail

out=${1:?usage: seed_corpus.sh OUT_DIR}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
data=$root/data

seed() { # seed FUZZER FILE...: copies the existing files into the fuzzer's corpus
  local fuzzer=$1 file
  shift
  mkdir -p "$out/$fuzzer"
  for file in "$@"; do
    [[ -f $file ]] && cp "$file" "$out/$fuzzer/"
  done
  return 0
}

shopt -s nullglob
for fuzzer in fuzz_xyz fuzz_xyz_exact; do
  seed $fuzzer "$data"/*.xyz "$data"/bad/*.xyz "$root"/fuzz/findings/xyz_*
done
printf '0 0 1/3\n1/2 0 -7/9\n0 0.1 2\n# exact decimals and fractions\n' >"$out/fuzz_xyz_exact/fractions.xyz"
seed fuzz_npy "$data"/*.npy "$data"/bad/*.npy "$root"/fuzz/findings/*.npy
seed fuzz_query "$data"/*.xy "$data"/bad/*.xy "$data"/franke_100.xyz "$root"/fuzz/findings/query_*
for fuzzer in fuzz_spline fuzz_spline_exact; do
  seed $fuzzer "$data"/*.spline "$data"/bad/*.spline "$root"/fuzz/findings/spline_*
done
seed fuzz_surface "$data"/*.surface "$data"/bad/*.surface "$root"/fuzz/findings/surface_*
for format in off obj ply stl; do
  seed fuzz_$format "$data"/*.$format "$data"/bad/*.$format "$root"/fuzz/findings/*.$format
done

# OFF "[N]OFF / V F E / V vertex lines / F face lines" to the other formats (triangles).
convert() { # convert FORMAT OFF_FILE
  awk -v format="$1" '
    BEGIN { v = 0; f = 0 }
    /^[ \t]*#/ || NF == 0 { next }
    !header_done { if ($1 ~ /OFF$/) next; V = $1 + 0; F = $2 + 0; header_done = 1; next }
    v < V { x[v] = $1; y[v] = $2; z[v] = $3; v++; next }
    f < F { n[f] = $1; for (i = 1; i <= $1; i++) c[f, i] = $(i + 1); f++ }
    END {
      if (format == "obj") {
        for (i = 0; i < V; i++) print "v", x[i], y[i], z[i]
        for (i = 0; i < F; i++) { s = "f"; for (k = 1; k <= n[i]; k++) s = s " " c[i, k] + 1; print s }
      } else if (format == "ply") {
        print "ply"; print "format ascii 1.0"
        print "element vertex " V; print "property double x"; print "property double y"
        print "property double z"; print "element face " F
        print "property list uchar int vertex_indices"; print "end_header"
        for (i = 0; i < V; i++) print x[i], y[i], z[i]
        for (i = 0; i < F; i++) { s = n[i]; for (k = 1; k <= n[i]; k++) s = s " " c[i, k]; print s }
      } else {
        print "solid converted"
        for (i = 0; i < F; i++) {
          print "  facet normal 0 0 1"; print "    outer loop"
          for (k = 1; k <= 3; k++) print "      vertex", x[c[i, k]], y[c[i, k]], z[c[i, k]]
          print "    endloop"; print "  endfacet"
        }
        print "endsolid converted"
      }
    }' "$2"
}
for format in obj ply stl; do
  for off in "$data"/height_field_with_hole.off "$data"/bad/quad.off "$data"/bad/nonmanifold.off; do
    convert $format "$off" >"$out/fuzz_$format/$(basename "$off" .off).$format"
  done
done

# One triangle (0,0,0) (1,0,0) (0,1,0) in binary: float32 1.0 is 00 00 80 3f little-endian.
zero='\0\0\0\0' one='\0\0\200\77'
{
  printf 'ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n'
  printf 'property float y\nproperty float z\nelement face 1\n'
  printf 'property list uchar int vertex_indices\nend_header\n'
  printf "$zero$zero$zero$one$zero$zero$zero$one$zero"
  printf '\3\0\0\0\0\1\0\0\0\2\0\0\0'
} >"$out/fuzz_ply/triangle_binary.ply"
{
  printf '%-80s' 'binary STL, one triangle'
  printf '\1\0\0\0'                               # the triangle count, uint32
  printf "$zero$zero$one"                         # the normal
  printf "$zero$zero$zero$one$zero$zero$zero$one$zero" # the vertices
  printf '\0\0'                                   # the attribute byte count
} >"$out/fuzz_stl/triangle_binary.stl"
