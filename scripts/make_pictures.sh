#!/usr/bin/env bash
# Regenerates the README and manual pictures in doc/Triangular_spline/fig/ from the current
# code: builds tspline, runs `tspline demo` (which ends with its pictures, 640x480) and
# `tspline render` on the saved demo spline, and copies the PNGs. Deterministic: the same
# code gives the same bytes, so `git status` shows whether the pictures changed.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
fig=doc/Triangular_spline/fig
max_bytes=153600 # keep each picture under ~150 KB

if [[ ! -f "$BUILD_DIR/CMakeCache.txt" ]]; then
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$BUILD_DIR" --target tspline -j "$(nproc)"
tspline="$BUILD_DIR/src/tspline/tspline"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$tspline" demo --output "$work" >/dev/null

mkdir -p "$fig"
for mode in shaded curvature isophotes net; do
  cp "$work/demo_$mode.png" "$fig/tour_$mode.png"
done
# The curvature of the demo surface seen from above, with a fixed colour range.
"$tspline" render --input "$work/demo.spline" --output "$fig/tour_curvature_top.png" \
  --mode curvature --view 0,90 --size 600x450 --range 4 >/dev/null

# Curvature of exp(x) sin(2y) (negative everywhere, -1 <= K < 0) from 1000 scattered
# points: the default adaptive fit, the minimal-energy fit, and the tangent-plane fit.
for fit in adaptive energy tangent; do
  "$tspline" c1 --input data/expsin_1000.xyz --fit "$fit" --output "$work/expsin_$fit.spline" >/dev/null
  "$tspline" render --input "$work/expsin_$fit.spline" --output "$fig/expsin_curvature_$fit.png" \
    --mode curvature --view 0,90 --size 400x300 --range 1 >/dev/null
done

# The convergence plot of the manual, where python3-numpy (and, for its reference curve,
# python3-scipy) are installed: python3-matplotlib draws it.
if /usr/bin/python3 -c "import numpy, matplotlib" 2>/dev/null; then
  /usr/bin/python3 benchmark/convergence.py --tspline "$tspline" --fits adaptive,local:3,energy,tangent \
    --plot "$fig/convergence.png" >/dev/null
fi

# One figure for each of Mann's and Fang's sections of the manual.
"$tspline" mann --input data/franke_100.xyz --mesh "$work/mann.ply" >/dev/null
"$tspline" render --input "$work/mann.ply" --output "$fig/mann_franke.png" --size 480x360 >/dev/null
"$tspline" blend --shape ellipsoid --order 2 --variant open --output "$work/ellipsoid.ply" >/dev/null
"$tspline" render --input "$work/ellipsoid.ply" --output "$fig/fang_ellipsoid_curvature.png" \
  --mode curvature --size 480x360 >/dev/null
# Where the curvature comes from (manual): the same ellipsoid with the colours saturating at
# |K| = 0.3 (the true minimum is 0.25), with the thesis' vertex surfaces and with ours that
# fit the neighbours' normals.
for method in least normals; do
  "$tspline" blend --shape ellipsoid --vertex-surface $method --resolution 16 \
    --output "$work/ellipsoid_$method.ply" >/dev/null
  "$tspline" render --input "$work/ellipsoid_$method.ply" --mode curvature --range 0.3 \
    --view -35,20 --size 360x270 --output "$fig/fang_ellipsoid_low_$method.png" >/dev/null
done

# Fang §5.4, Figs. 5.8-5.13: his improved (open-set) blend with d = 0, 1, 2 and Nielson's
# side-vertex interpolant of the same ellipsoid and perturbed meshes, shaded, Gaussian
# curvature (colours saturating at |K| = 2 for all eight surfaces) and isophotes.
for shape in ellipsoid perturbed; do
  for method in d0 d1 d2 nielson; do
    if [[ $method == nielson ]]; then
      scheme=(--scheme nielson)
    else
      scheme=(--order "${method#d}")
    fi
    "$tspline" blend --shape $shape "${scheme[@]}" --resolution 16 \
      --output "$work/fn_${shape}_$method.ply" >/dev/null
    for mode in shaded curvature isophotes; do
      extra=()
      [[ $mode == curvature ]] && extra=(--range 2)
      "$tspline" render --input "$work/fn_${shape}_$method.ply" --mode $mode "${extra[@]}" \
        --view -35,20 --size 360x270 --output "$fig/fang_nielson_${shape}_${method}_$mode.png" \
        >/dev/null
    done
  done
done

# Xu's pseudo-AG^1 surfaces over closed meshes (manual, AG1.md §6 "Pictures"): the control net
# of the exact tetrahedron in the colours of Xu's Fig. 6.9, isophotes of the icosahedron (the
# bands kink where the tangent planes jump), the torus's edges coloured by their largest normal
# jump (the numbers of the pseudo-ag1 report), the octahedron shaded.
for shape in tetrahedron icosahedron torus octahedron; do
  preset=thesis
  [[ $shape == tetrahedron ]] && preset=exact
  "$tspline" pseudo-ag1 --shape $shape --preset $preset --save "$work/pag1_$shape.surface" >/dev/null
done
"$tspline" render --input "$work/pag1_tetrahedron.surface" --mode net --view 30,20 --size 640x480 \
  --output "$fig/pag1_tetrahedron_net.png" >/dev/null
"$tspline" render --input "$work/pag1_icosahedron.surface" --mode isophotes --size 640x480 \
  --output "$fig/pag1_icosahedron_isophotes.png" >/dev/null
"$tspline" render --input "$work/pag1_torus.surface" --mode jump --size 640x480 \
  --output "$fig/pag1_torus_jump.png" >/dev/null
"$tspline" render --input "$work/pag1_octahedron.surface" --mode shaded --size 640x480 \
  --output "$fig/pag1_octahedron_shaded.png" >/dev/null
# Xu's Fig. 6.10: the umbrellas (corner point and stars of every vertex, in its corner plane),
# and the octahedron again with split normals: each patch its own, so the jumps show as creases.
"$tspline" render --input "$work/pag1_icosahedron.surface" --mode net --umbrellas --size 640x480 \
  --output "$fig/pag1_icosahedron_umbrellas.png" >/dev/null
"$tspline" render --input "$work/pag1_octahedron.surface" --mode shaded --split-normals \
  --size 640x480 --output "$fig/pag1_octahedron_split.png" >/dev/null
# A real mesh: CGAL's elephant (data/elephant.off, 5558 faces, from CGAL's sample data in
# Debian's libcgal-demo, data/meshes/elephant.off). Seen from the side (y is up in the file).
# Its jumps: max 40.8 deg on a single edge, mean of the per-edge maxima 3.6 deg, so the colours
# saturate at 10 deg (503 of 8337 edges are red), and one sample per pixel keeps the 8337 thin
# lines under the size limit (185 KB with 2x2 samples); the isophotes use 6 bands on 4^3
# triangles per patch, so that the dimples of every patch stay readable.
"$tspline" pseudo-ag1 --input data/elephant.off --save "$work/pag1_elephant.surface" >/dev/null
"$tspline" render --input "$work/pag1_elephant.surface" --mode jump --range 10 --view 20,70 \
  --samples 1 --size 640x480 --output "$fig/pag1_elephant_jump.png" >/dev/null
"$tspline" render --input "$work/pag1_elephant.surface" --mode isophotes --bands 6 --levels 3 \
  --view 20,70 --size 640x480 --output "$fig/pag1_elephant_isophotes.png" >/dev/null

for picture in "$fig"/*.png; do
  bytes=$(stat -c %s "$picture")
  echo "$picture: $bytes bytes"
  if ((bytes > max_bytes)); then
    echo "make_pictures.sh: $picture is larger than $max_bytes bytes" >&2
    exit 1
  fi
done
