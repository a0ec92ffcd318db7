// GeoTIFF output of `tspline eval --grid` (issue 15), through GDAL where it was found at
// configure time (Debian: libgdal-dev, an optional dependency). Without it the writer refuses
// with one line naming the missing dependency.

#ifndef TSPLINE_GEOTIFF_H
#define TSPLINE_GEOTIFF_H

#include <string>
#include <vector>

namespace tspline {

// Whether this tspline was built with GDAL.
bool geotiff_available();

// The one-line reason a .tif output is refused in a build without GDAL.
std::string geotiff_unavailable_message();

// A float64 GeoTIFF of nx x ny pixels, rows from north to south, one band per name (e.g. z,
// zx, zy), NaN as no-data, DEFLATE-compressed. The centre of pixel (0, 0) is at (west, north),
// pixels are dx wide and dy high; no coordinate reference system is set (the spline has none).
class Geotiff_writer {
public:
  // Throws std::runtime_error naming `path` (GDAL's message) or, without GDAL,
  // geotiff_unavailable_message().
  Geotiff_writer(const std::string& path, long long nx, long long ny,
                 const std::vector<std::string>& bands, double west, double north, double dx,
                 double dy);
  ~Geotiff_writer(); // closes an unclosed file; errors are then lost: call close()
  Geotiff_writer(const Geotiff_writer&) = delete;
  Geotiff_writer& operator=(const Geotiff_writer&) = delete;

  // Rows [first, first + count) of every band: values[b][r * nx + i], row r counted from
  // `first`, column i from the west.
  void write_rows(long long first, long long count, const std::vector<std::vector<double>>& values);
  // Flushes and closes; throws std::runtime_error if GDAL fails (e.g. a full disk).
  void close();

private:
  void* m_dataset = nullptr; // GDALDatasetH
  std::string m_path;
  long long m_nx = 0;
};

} // namespace tspline

#endif // TSPLINE_GEOTIFF_H
