// Scattered points and query points from the files the CLI accepts besides text: NumPy .npy
// arrays (columns chosen by index with --columns). Templates on the kernel, instantiated in
// the jobs that read points (c1, mann, eval).

#ifndef TSPLINE_POINT_INPUT_H
#define TSPLINE_POINT_INPUT_H

#include "csv_input.h"
#include "files.h"

#include <CGAL/Triangular_spline/IO/npy.h>
#include <CGAL/Triangular_spline/IO/scattered_data.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace tspline {

inline CGAL::Triangular_spline::Npy_array read_npy_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error("cannot open '" + path + "'");
  return CGAL::Triangular_spline::read_npy(in, path);
}

// x, y, z (zx, zy with `gradients`) from the columns of a .npy file that `columns` names by
// index ("0,1,2"; empty: all of an (n, 3) array, or (n, 5) with gradients).
template <class K>
CGAL::Triangular_spline::Scattered_data<K>
read_npy_scattered(const std::string& path, const std::string& columns, bool gradients) {
  const CGAL::Triangular_spline::Npy_array array = read_npy_file(path);
  return CGAL::Triangular_spline::scattered_data_from_npy<K>(
      array, path, npy_column_indices(columns, array.rows, array.columns, gradients, path));
}

// Query points from a text file ('x y' per line) or a .npy array (its columns 0 and 1).
template <class K>
std::vector<typename K::Point_2> read_query_file(const std::string& path) {
  if (lowercase_extension(path) == "npy")
    return CGAL::Triangular_spline::query_points_from_npy<K>(read_npy_file(path), path);
  std::ifstream in = open_input(path);
  return CGAL::Triangular_spline::read_query_points<K>(in, path);
}

} // namespace tspline

#endif // TSPLINE_POINT_INPUT_H
