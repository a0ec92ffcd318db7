// Test helper (built with GDAL only): prints band 1 of a GeoTIFF in the layout of the ESRI ASCII
// grid `tspline eval` writes (%.17g, NaN as -9999), so that a test can compare the two files
// byte for byte; with a second argument N, first the band count and names, the pixel width and
// height, and NaN as 'nan' (N: the expected band count, exit 1 otherwise).
// usage: geotiff_dump FILE.tif [N]

#include <gdal.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char** argv) {
  if (argc < 2)
    return 2;
  GDALAllRegister();
  GDALDatasetH d = GDALOpen(argv[1], GA_ReadOnly);
  if (!d)
    return 1;
  const int nx = GDALGetRasterXSize(d), ny = GDALGetRasterYSize(d), n = GDALGetRasterCount(d);
  double t[6];
  if (GDALGetGeoTransform(d, t) != CE_None || t[2] != 0 || t[4] != 0)
    return 1;
  const bool verbose = argc > 2;
  if (verbose) {
    if (n != std::atoi(argv[2]))
      return 1;
    std::printf("bands %d", n);
    for (int b = 1; b <= n; ++b)
      std::printf(" %s", GDALGetDescription(GDALGetRasterBand(d, b)));
    std::printf("\n");
  }
  GDALRasterBandH band = GDALGetRasterBand(d, 1);
  int has_nodata = 0;
  const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
  if (!has_nodata || !std::isnan(nodata) || GDALGetRasterDataType(band) != GDT_Float64)
    return 1;
  std::printf("ncols %d\nnrows %d\nxllcorner %.17g\nyllcorner %.17g\n", nx, ny, t[0],
              t[3] + ny * t[5]);
  if (verbose)
    std::printf("cellsize %.17g %.17g\nNODATA_value nan\n", t[1], -t[5]);
  else
    std::printf("cellsize %.17g\nNODATA_value -9999\n", t[1]);
  std::vector<double> row(static_cast<std::size_t>(nx));
  for (int y = 0; y < ny; ++y) {
    if (GDALRasterIO(band, GF_Read, 0, y, nx, 1, row.data(), nx, 1, GDT_Float64, 0, 0) != CE_None)
      return 1;
    for (int x = 0; x < nx; ++x) {
      const double v = row[std::size_t(x)];
      if (std::isnan(v))
        std::printf(verbose ? "nan" : "-9999");
      else
        std::printf("%.17g", v);
      std::printf(x + 1 < nx ? " " : "\n");
    }
  }
  GDALClose(d);
  return 0;
}
