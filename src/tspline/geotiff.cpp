// GeoTIFF through GDAL's C API (TSPLINE_HAVE_GDAL), or the refusal without it.

#include "geotiff.h"

#include <stdexcept>

#ifdef TSPLINE_HAVE_GDAL
#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <gdal.h>

#include <cmath>
#include <limits>
#endif

namespace tspline {

std::string geotiff_unavailable_message() {
  return "GeoTIFF output needs GDAL, which this tspline was built without (Debian: install "
         "libgdal-dev and configure again); write an ESRI ASCII grid (.asc) or CSV instead";
}

#ifdef TSPLINE_HAVE_GDAL

namespace {

// GDAL's last message, or `fallback`; GDAL prints nothing itself (quiet handler below), so the
// CLI keeps its one-line errors.
std::string gdal_error(const std::string& path, const std::string& fallback) {
  const char* message = CPLGetLastErrorMsg();
  return "cannot write '" + path + "': " + (message && *message ? std::string(message) : fallback);
}

} // namespace

bool geotiff_available() {
  return true;
}

Geotiff_writer::Geotiff_writer(const std::string& path, long long nx, long long ny,
                               const std::vector<std::string>& bands, double west, double north,
                               double dx, double dy)
    : m_path(path), m_nx(nx) {
  CPLSetErrorHandler(CPLQuietErrorHandler);
  CPLErrorReset();
  GDALAllRegister();
  GDALDriverH driver = GDALGetDriverByName("GTiff");
  if (!driver)
    throw std::runtime_error(gdal_error(path, "GDAL has no GTiff driver"));
  char** options = nullptr;
  options = CSLSetNameValue(options, "COMPRESS", "DEFLATE");
  options = CSLSetNameValue(options, "PREDICTOR", "3"); // floating-point predictor
  options = CSLSetNameValue(options, "BIGTIFF", "IF_SAFER");
  m_dataset = GDALCreate(driver, path.c_str(), static_cast<int>(nx), static_cast<int>(ny),
                         static_cast<int>(bands.size()), GDT_Float64, options);
  CSLDestroy(options);
  if (!m_dataset)
    throw std::runtime_error(gdal_error(path, "GDALCreate failed"));
  // GDAL's geotransform names the outer corner of pixel (0, 0): half a pixel from its centre.
  double transform[6] = {west - dx / 2, dx, 0, north + dy / 2, 0, -dy};
  bool ok = GDALSetGeoTransform(m_dataset, transform) == CE_None;
  for (std::size_t b = 0; b < bands.size() && ok; ++b) {
    GDALRasterBandH band = GDALGetRasterBand(m_dataset, static_cast<int>(b + 1));
    GDALSetDescription(band, bands[b].c_str());
    ok = GDALSetRasterNoDataValue(band, std::numeric_limits<double>::quiet_NaN()) == CE_None;
  }
  if (!ok) {
    const std::string message = gdal_error(path, "cannot set the georeferencing");
    GDALClose(m_dataset);
    m_dataset = nullptr;
    throw std::runtime_error(message);
  }
}

Geotiff_writer::~Geotiff_writer() {
  if (m_dataset)
    GDALClose(m_dataset);
}

void Geotiff_writer::write_rows(long long first, long long count,
                                const std::vector<std::vector<double>>& values) {
  for (std::size_t b = 0; b < values.size(); ++b) {
    GDALRasterBandH band = GDALGetRasterBand(m_dataset, static_cast<int>(b + 1));
    // RasterIO takes a non-const buffer also for writing
    double* data = const_cast<double*>(values[b].data());
    if (GDALRasterIO(band, GF_Write, 0, static_cast<int>(first), static_cast<int>(m_nx),
                     static_cast<int>(count), data, static_cast<int>(m_nx), static_cast<int>(count),
                     GDT_Float64, 0, 0) != CE_None)
      throw std::runtime_error(gdal_error(m_path, "writing rows failed"));
  }
}

void Geotiff_writer::close() {
  GDALDatasetH dataset = m_dataset;
  m_dataset = nullptr;
  CPLErrorReset();
  // GDALClose returns CPLErr only from GDAL 3.7 on: check the error state instead.
  GDALClose(dataset);
  if (CPLGetLastErrorType() >= CE_Failure)
    throw std::runtime_error(gdal_error(m_path, "closing the file failed"));
}

#else

bool geotiff_available() {
  return false;
}

Geotiff_writer::Geotiff_writer(const std::string&, long long, long long,
                               const std::vector<std::string>&, double, double, double, double) {
  throw std::runtime_error(geotiff_unavailable_message());
}

Geotiff_writer::~Geotiff_writer() = default;

void Geotiff_writer::write_rows(long long, long long, const std::vector<std::vector<double>>&) {}

void Geotiff_writer::close() {}

#endif

} // namespace tspline
