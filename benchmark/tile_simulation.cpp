// Tile-parallel fitting, simulated on one machine (issue 12, doc/design/tile_parallel.md §8).
//
// N random points of a terrain-like function on the unit square are cut into T x T tiles:
// half-open cores meeting at the seams x, y = k/T, each read with a halo of H point
// spacings. Every tile triangulates its core plus halo alone, in its own process (its peak
// memory is its own), owns the faces whose centroid lies in its core, and checks that it may
// trust them: a face whose circumdisk may hold a point the tile did not read is uncertain,
// and an owned face within R rings of an uncertain face means the halo is too small (the
// tile is triangulated again with twice the halo). Then it fits and writes its owned faces.
// The single-machine spline of all the points is the reference. The program reports whether
// the owned faces are exactly the reference triangulation, and whether each owned face's 21
// control values and its plan (free or dependent) are bit-identical to the reference's, with
// the differences where they are not, by distance to the nearest seam.
//
// Not simulated: the black/white exchange of the design (§5) needs a library hook to fix
// free values from outside; here every tile solves its own untrusted vertices (--fit
// adaptive). --fit local has no global solve: every owned face must come out bit-identical.
//
// Build: make tile-simulation (not in the default build: a measurement, not a tool).
// Usage: tile_simulation [--n N] [--tiles T] [--halo H] [--rings R] [--retries K]
//                        [--fit adaptive|local] [--seed S] [--work DIR]
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangular_spline/Domain/delaunay_domain.h>
#include <CGAL/Triangular_spline/Xu/make_c1_quintic_spline.h>
#include <CGAL/Triangular_spline/certify.h>
#include <CGAL/Triangular_spline/internal/vertex_rings.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace TS = CGAL::Triangular_spline;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Spline = TS::C1_quintic_spline<K>;

namespace {

struct Options {
  std::size_t n = 1000000;
  int tiles = 2;
  double halo = 26;   // point spacings: 13 rings (design §2) times a safety factor 2
  int rings = 13;     // how far, in rings, the plan, fits and propagation read (design §2)
  int retries = 0;    // triangulations with twice the halo while owned faces stay unchecked
  bool local = false; // --fit local instead of the default adaptive
  std::uint64_t seed = 12;
  std::string work = "/tmp/tile_simulation";
};

// Terrain-like: five octaves of rotated waves, and ridges (kinks along lines crossing both
// seams) that the local polynomials cannot resolve, so the energy solve has work near seams.
double terrain(double x, double y) {
  double z = 0, amplitude = 1, frequency = 3;
  for (int k = 0; k < 5; ++k) {
    const double a = 0.7 * k + 0.3;
    z += amplitude * std::sin(frequency * (std::cos(a) * x + std::sin(a) * y) + k);
    amplitude *= 0.5;
    frequency *= 2.1;
  }
  return z + 0.5 * std::abs(std::sin(7.0 * (0.8 * x + 0.6 * y))) +
         0.3 * std::abs(std::sin(11.0 * (0.3 * x - 0.95 * y)));
}

// One face as a tile or the reference wrote it: the global ids of its vertices ascending,
// its control values b_{ijk} (i counting g[0], j g[1], k g[2]) in a fixed order of the
// multi-indices, and which of them are free parameters.
struct Record {
  std::array<std::uint32_t, 3> g;
  std::uint32_t free_mask;
  std::array<double, 21> b;
};
static_assert(sizeof(Record) == 184, "packed record");

constexpr std::uint32_t unchecked_bit = 1u << 31; // in free_mask: the tile could not check it

bool key_less(const Record& a, const Record& b) {
  return a.g < b.g;
}

// The centroid of a face, computed from its points in the order of their global ids: every
// tile rounds it the same way, so exactly one tile owns the face. (The design's circumcentre
// fails at the hull: a thin hull face's circumcentre lies far along the hull, in a tile that
// never reads the face's points.)
K::Point_2 centroid(const std::array<K::Point_2, 3>& p) {
  return K::Point_2((p[0].x() + p[1].x() + p[2].x()) / 3, (p[0].y() + p[1].y() + p[2].y()) / 3);
}

struct Tile {
  double core[4];   // xmin, xmax, ymin, ymax (half-open; infinite at the data's border)
  double region[4]; // core plus halo
  double halo = 0;
  void set_halo(double h) {
    halo = h;
    for (int k = 0; k < 4; ++k)
      region[k] = core[k] + (k % 2 == 0 ? -h : h);
  }
  bool in_core(const K::Point_2& c) const {
    return c.x() >= core[0] && c.x() < core[1] && c.y() >= core[2] && c.y() < core[3];
  }
  bool in_region(const K::Point_2& p) const {
    return p.x() >= region[0] && p.x() < region[1] && p.y() >= region[2] && p.y() < region[3];
  }
};

// Whether the circumdisk of (p0, p1, p2) holds no point of the data's bounding box `box`
// (xmin, xmax, ymin, ymax) outside the tile's region, decided exactly (Epeck): then no point
// the tile did not read lies in the disk, and the face is a face of the global Delaunay
// triangulation. Only the box is known globally; the disk of a thin hull face reaches far
// outside the region, but not into the box.
bool disk_inside(const std::array<K::Point_2, 3>& p, const Tile& t, const double* box) {
  using E = CGAL::Exact_predicates_exact_constructions_kernel;
  const E::Point_2 a(p[0].x(), p[0].y()), b(p[1].x(), p[1].y()), c(p[2].x(), p[2].y());
  const E::Point_2 o = CGAL::circumcenter(a, b, c);
  const E::FT r2 = CGAL::squared_distance(o, a);
  for (int side = 0; side < 4; ++side) {
    // the part of the box beyond this side of the region: a closed rectangle
    std::array<double, 4> part = {box[0], box[1], box[2], box[3]};
    const double bound = t.region[side];
    if (side % 2 == 0) { // below a lower bound
      if (!(bound > box[side]))
        continue;
      part[std::size_t(side + 1)] = (std::min)(bound, box[side + 1]);
    } else { // at or above an upper bound
      if (!(bound <= box[side]))
        continue;
      part[std::size_t(side - 1)] = (std::max)(bound, box[side - 1]);
    }
    auto gap = [](const E::FT& v, double low, double high) {
      return v < E::FT(low) ? E::FT(low) - v : v > E::FT(high) ? v - E::FT(high) : E::FT(0);
    };
    const E::FT dx = gap(o.x(), part[0], part[1]), dy = gap(o.y(), part[2], part[3]);
    if (!(dx * dx + dy * dy > r2))
      return false;
  }
  return true;
}

struct Summary {
  double seconds = 0, fit_seconds = 0, halo = 0;
  int retries = 0; // triangulations again with twice the halo
  std::size_t points = 0, faces = 0, owned = 0, owned_unchecked = 0;
  std::size_t trust[3] = {0, 0, 0};
  bool certified = false;
  double max_residual = 0;
  long peak_kb = 0;
};

// The tile's points within `halo` of its core (all of them for the reference), their
// global ids, and its Delaunay domain.
struct Tile_domain {
  TS::Planar_domain<K> domain;
  std::vector<double> values;
  std::vector<std::uint32_t> global; // global id of every domain vertex
};

Tile_domain triangulate(const TS::Scattered_data<K>& all, const Tile* tile) {
  TS::Scattered_data<K> data;
  std::vector<std::uint32_t> ids;
  for (std::size_t i = 0; i < all.points.size(); ++i)
    if (!tile || tile->in_region(all.points[i])) {
      data.points.push_back(all.points[i]);
      data.values.push_back(all.values[i]);
      ids.push_back(std::uint32_t(i));
    }
  std::vector<std::size_t> input_index;
  auto [domain, values] = TS::delaunay_domain(data, &input_index);
  Tile_domain t{std::move(domain), std::move(values), {}};
  for (std::size_t v : input_index)
    t.global.push_back(ids[v]);
  return t;
}

// A face's corners in the order of their global ids.
std::array<int, 3> corners_by_id(const TS::Planar_domain<K>& d,
                                 const std::vector<std::uint32_t>& global, std::uint32_t f) {
  const auto& face = d.face(f);
  std::array<int, 3> order = {0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return global[face[std::size_t(a)]] < global[face[std::size_t(b)]];
  });
  return order;
}

std::array<K::Point_2, 3> points_by_id(const TS::Planar_domain<K>& d,
                                       const std::vector<std::uint32_t>& global, std::uint32_t f) {
  const auto& face = d.face(f);
  const auto order = corners_by_id(d, global, f);
  return {d.point(face[std::size_t(order[0])]), d.point(face[std::size_t(order[1])]),
          d.point(face[std::size_t(order[2])])};
}

// The faces that cannot be trusted: within `rings` rings of a face whose circumdisk may
// hold a point the tile did not read (such a face may not be global, and its neighbourhood
// is cut off).
std::vector<char> unchecked_faces(const Tile_domain& t, const Tile& tile, const double* box,
                                  int rings) {
  const auto& d = t.domain;
  std::vector<int> ring(d.number_of_vertices(), -1);
  std::vector<std::uint32_t> front;
  for (std::uint32_t f = 0; f < d.number_of_faces(); ++f)
    if (!disk_inside(points_by_id(d, t.global, f), tile, box))
      for (std::uint32_t v : d.face(f))
        if (ring[v] < 0) {
          ring[v] = 0;
          front.push_back(v);
        }
  TS::internal::grow_vertex_rings(d, ring, std::move(front), rings);
  std::vector<char> unchecked(d.number_of_faces(), 0);
  for (std::uint32_t f = 0; f < d.number_of_faces(); ++f)
    for (std::uint32_t v : d.face(f))
      unchecked[f] = unchecked[f] || ring[v] >= 0;
  return unchecked;
}

// Builds the spline of the points in `tile` (all of them for the reference) and writes the
// faces it owns to `path`; runs in a child process.
Summary build(const TS::Scattered_data<K>& all, Tile* tile, const double* box, const Options& o,
              const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  Summary s;
  Tile_domain t = triangulate(all, tile);
  std::vector<char> unchecked;
  if (tile) {
    for (;;) {
      s.halo = tile->halo;
      unchecked = unchecked_faces(t, *tile, box, o.rings);
      s.owned_unchecked = 0;
      for (std::uint32_t f = 0; f < t.domain.number_of_faces(); ++f)
        s.owned_unchecked +=
            unchecked[f] && tile->in_core(centroid(points_by_id(t.domain, t.global, f)));
      if (s.owned_unchecked == 0 || s.retries == o.retries)
        break;
      ++s.retries;
      tile->set_halo(2 * tile->halo);
      t = triangulate(all, tile);
    }
  }
  s.points = t.domain.number_of_vertices();
  s.faces = t.domain.number_of_faces();
  const auto fit_start = std::chrono::steady_clock::now();
  TS::Fit_statistics statistics;
  const Spline spline = TS::make_c1_quintic_spline(
      std::move(t.domain), t.values,
      TS::parameters::data_fit(o.local ? TS::Fit::LOCAL_POLYNOMIAL : TS::Fit::ADAPTIVE,
                               TS::parameters::fit_statistics(statistics)));
  s.fit_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - fit_start).count();
  for (int k = 0; k < 3; ++k)
    s.trust[k] = statistics.vertices_by_trust[std::size_t(k)];
  double scale = 1;
  for (double v : spline.values())
    scale = (std::max)(scale, std::abs(v));
  const auto certificate =
      TS::certify_continuity(spline, 1, TS::parameters::residual_tolerance(1e-10 * scale));
  s.certified = certificate.certified;
  s.max_residual = certificate.max_residual;

  std::ofstream out(path, std::ios::binary);
  std::vector<Record> buffer;
  buffer.reserve(1 << 16);
  const auto& d = spline.domain();
  for (std::uint32_t f = 0; f < d.number_of_faces(); ++f) {
    const auto& face = d.face(f);
    const std::array<int, 3> order = corners_by_id(d, t.global, f);
    if (tile && !tile->in_core(centroid(points_by_id(d, t.global, f))))
      continue;
    ++s.owned;
    Record r;
    r.free_mask = tile && unchecked[f] ? unchecked_bit : 0;
    for (int c = 0; c < 3; ++c)
      r.g[std::size_t(c)] = t.global[face[std::size_t(order[std::size_t(c)])]];
    int n = 0;
    for (int i = 5; i >= 0; --i)
      for (int j = 5 - i; j >= 0; --j, ++n) {
        TS::Multi_index m; // in the face's own corner order
        m[order[0]] = i;
        m[order[1]] = j;
        m[order[2]] = 5 - i - j;
        const Spline::Slot slot = spline.slot(f, m);
        r.b[std::size_t(n)] = spline.value(slot);
        if (spline.is_free(slot))
          r.free_mask |= 1u << n;
      }
    buffer.push_back(r);
    if (buffer.size() == buffer.capacity()) {
      out.write(reinterpret_cast<const char*>(buffer.data()),
                std::streamsize(buffer.size() * sizeof(Record)));
      buffer.clear();
    }
  }
  out.write(reinterpret_cast<const char*>(buffer.data()),
            std::streamsize(buffer.size() * sizeof(Record)));
  if (!out)
    throw std::runtime_error("cannot write " + path);
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return s;
}

// Runs build() in a child process: its peak memory is measured alone.
Summary run_child(const TS::Scattered_data<K>& all, const Tile* tile, const double* box,
                  const Options& o, const std::string& path) {
  const std::string summary_path = path + ".summary";
  std::cout.flush();
  const pid_t pid = fork();
  if (pid < 0)
    throw std::runtime_error("fork failed");
  if (pid == 0) {
    int status = 0;
    try {
      std::optional<Tile> own; // the child may widen its halo
      if (tile)
        own = *tile;
      Summary s = build(all, own ? &*own : nullptr, box, o, path);
      std::ofstream(summary_path, std::ios::binary)
          .write(reinterpret_cast<const char*>(&s), sizeof s);
    } catch (const std::exception& e) {
      std::cerr << "tile_simulation: " << e.what() << "\n";
      status = 1;
    }
    std::_Exit(status);
  }
  int status = 0;
  struct rusage usage;
  if (wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("a build failed");
  Summary s;
  std::ifstream(summary_path, std::ios::binary).read(reinterpret_cast<char*>(&s), sizeof s);
  s.peak_kb = usage.ru_maxrss;
  return s;
}

std::vector<Record> read_records(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::size_t bytes = std::size_t(in.tellg());
  std::vector<Record> records(bytes / sizeof(Record));
  in.seekg(0);
  in.read(reinterpret_cast<char*>(records.data()), std::streamsize(bytes));
  return records;
}

bool parse(int argc, char** argv, Options& o) {
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i], v = argv[i + 1];
    if (a == "--n")
      o.n = std::size_t(std::stod(v));
    else if (a == "--tiles")
      o.tiles = std::stoi(v);
    else if (a == "--halo")
      o.halo = std::stod(v);
    else if (a == "--seed")
      o.seed = std::stoull(v);
    else if (a == "--retries")
      o.retries = std::stoi(v);
    else if (a == "--rings")
      o.rings = std::stoi(v);
    else if (a == "--fit" && (v == "local" || v == "adaptive"))
      o.local = v == "local";
    else if (a == "--work")
      o.work = v;
    else
      return false;
  }
  return argc % 2 == 1 && o.n >= 100 && o.n < (std::size_t(1) << 32) && o.tiles >= 1 &&
         o.tiles <= 16 && o.halo >= 0 && o.rings >= 0;
}

} // namespace

static int simulate(const Options& o) {
  std::mt19937_64 engine(o.seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  TS::Scattered_data<K> all;
  all.points.reserve(o.n);
  all.values.reserve(o.n);
  for (std::size_t i = 0; i < o.n; ++i) {
    const double x = uniform(engine), y = uniform(engine);
    all.points.emplace_back(x, y);
    all.values.push_back(terrain(x, y));
  }
  double box[4] = {1, 0, 1, 0}; // the data's bounding box
  for (const auto& p : all.points) {
    box[0] = (std::min)(box[0], p.x());
    box[1] = (std::max)(box[1], p.x());
    box[2] = (std::min)(box[2], p.y());
    box[3] = (std::max)(box[3], p.y());
  }
  const double spacing = 1 / std::sqrt(double(o.n));
  const double H = o.halo * spacing;
  std::string mk = "mkdir -p '" + o.work + "'";
  if (std::system(mk.c_str()) != 0)
    return 1;
  std::cout << "tile simulation: " << o.n << " points, " << o.tiles << " x " << o.tiles
            << " tiles, fit " << (o.local ? "local" : "adaptive") << ", halo " << o.halo
            << " spacings (" << H << "), checked " << o.rings << " rings deep\n";

  std::vector<Tile> tiles;
  const double inf = std::numeric_limits<double>::infinity();
  for (int ty = 0; ty < o.tiles; ++ty)
    for (int tx = 0; tx < o.tiles; ++tx) {
      Tile t;
      t.core[0] = tx == 0 ? -inf : double(tx) / o.tiles;
      t.core[1] = tx + 1 == o.tiles ? inf : double(tx + 1) / o.tiles;
      t.core[2] = ty == 0 ? -inf : double(ty) / o.tiles;
      t.core[3] = ty + 1 == o.tiles ? inf : double(ty + 1) / o.tiles;
      t.set_halo(H);
      tiles.push_back(t);
    }

  const Summary reference = run_child(all, nullptr, box, o, o.work + "/reference.bin");
  std::printf("%-10s %9s %9s %9s %6s %5s %8s %8s %8s %9s %4s %s\n", "build", "points", "faces",
              "owned", "halo", "again", "wall s", "fit s", "peak MB", "untrust.", "C1",
              "max residual");
  auto row = [&](const char* name, const Summary& s) {
    std::printf("%-10s %9zu %9zu %9zu %6.0f %5d %8.2f %8.2f %8.0f %9zu %4s %.2e\n", name, s.points,
                s.faces, s.owned, s.halo / spacing, s.retries, s.seconds, s.fit_seconds,
                double(s.peak_kb) / 1024, s.trust[1] + s.trust[2], s.certified ? "yes" : "NO",
                s.max_residual);
  };
  row("reference", reference);
  std::vector<Summary> summaries;
  for (std::size_t t = 0; t < tiles.size(); ++t) {
    summaries.push_back(
        run_child(all, &tiles[t], box, o, o.work + "/tile" + std::to_string(t) + ".bin"));
    row(("tile " + std::to_string(t)).c_str(), summaries.back());
  }

  // Compare every tile's owned faces with the reference's.
  std::vector<Record> ref = read_records(o.work + "/reference.bin");
  std::sort(ref.begin(), ref.end(), key_less);
  double value_scale = 0;
  for (const Record& r : ref)
    for (double b : r.b)
      value_scale = (std::max)(value_scale, std::abs(b));
  const double rounding = 1e-12 * value_scale; // differences up to this are round-off
  std::vector<char> seen(ref.size(), 0);
  const int bands = 6;
  const double band_edges[bands] = {2, 5, 10, 20, 50, inf}; // spacings from the nearest seam
  struct Band {
    std::size_t faces = 0, identical = 0, rounding = 0, larger = 0, free_differs = 0;
    double max_difference = 0;
  };
  // checked faces inside, within 20 spacings of the data's edge, and unchecked faces
  std::array<std::array<Band, bands>, 3> parts{};
  const char* part_names[3] = {"inside", "border", "unchecked"};
  std::size_t plan_differs_checked = 0;
  std::size_t owned = 0, missing = 0, twice = 0, plan_differs = 0, unchecked = 0;
  auto centroid = [&](const std::array<std::uint32_t, 3>& g) {
    double cx = 0, cy = 0;
    for (std::uint32_t v : g) {
      cx += all.points[v].x() / 3;
      cy += all.points[v].y() / 3;
    }
    return std::pair(cx, cy);
  };
  for (std::size_t t = 0; t < tiles.size(); ++t) {
    unchecked += summaries[t].owned_unchecked;
    for (const Record& r : read_records(o.work + "/tile" + std::to_string(t) + ".bin")) {
      ++owned;
      const auto it = std::lower_bound(ref.begin(), ref.end(), r, key_less);
      const auto [cx, cy] = centroid(r.g);
      if (it == ref.end() || it->g != r.g) {
        if (missing++ < 5)
          std::printf("owned by tile %zu, not in the reference: face at (%.6f, %.6f)\n", t, cx, cy);
        continue;
      }
      char& mark = seen[std::size_t(it - ref.begin())];
      twice += mark;
      mark = 1;
      double seam = inf; // distance of the centroid to the nearest interior seam
      for (int k = 1; k < o.tiles; ++k) {
        seam = (std::min)(seam, std::abs(cx - double(k) / o.tiles));
        seam = (std::min)(seam, std::abs(cy - double(k) / o.tiles));
      }
      int band = 0;
      while (seam / spacing > band_edges[band])
        ++band;
      const bool near_border = (std::min)({cx, 1 - cx, cy, 1 - cy}) / spacing <= 20;
      const bool checked = !(r.free_mask & unchecked_bit);
      Band& b = parts[!checked ? 2 : near_border ? 1 : 0][std::size_t(band)];
      ++b.faces;
      if ((r.free_mask & ~unchecked_bit) != it->free_mask) {
        ++plan_differs;
        if (checked && plan_differs_checked++ < 5)
          std::printf("plan differs from the reference in tile %zu: face at (%.6f, %.6f)\n", t, cx,
                      cy);
      }
      double diff = 0, free_diff = 0;
      for (int k = 0; k < 21; ++k) {
        const double d = std::abs(r.b[std::size_t(k)] - it->b[std::size_t(k)]);
        diff = (std::max)(diff, d);
        if (r.free_mask >> k & 1)
          free_diff = (std::max)(free_diff, d);
      }
      if (std::memcmp(r.b.data(), it->b.data(), sizeof r.b) == 0)
        ++b.identical;
      else if (diff <= rounding)
        ++b.rounding;
      else
        ++b.larger;
      b.free_differs += free_diff > 0;
      b.max_difference = (std::max)(b.max_difference, diff);
    }
  }
  std::size_t unowned = 0;
  for (std::size_t i = 0; i < ref.size(); ++i)
    if (!seen[i] && unowned++ < 5) {
      const auto [cx, cy] = centroid(ref[i].g);
      std::printf("reference face owned by no tile: at (%.6f, %.6f)\n", cx, cy);
    }
  std::printf("\ntriangulation: %zu reference faces; owned by the tiles %zu (not in the "
              "reference %zu, owned twice %zu); reference faces owned by no tile %zu; owned "
              "faces left unchecked (within the rings of an uncertain face after the last "
              "halo): %zu\n",
              ref.size(), owned, missing, twice, unowned, unchecked);
  std::printf("plan: owned faces whose free/dependent pattern differs from the reference: %zu "
              "(checked faces: %zu)\n",
              plan_differs, plan_differs_checked);
  std::printf("control values against the reference (round-off: at most %.1e):\n", rounding);
  std::printf("%-10s %-20s %9s %10s %10s %9s %11s %10s\n", "where", "distance to seam", "faces",
              "identical", "round-off", "larger", "free differ", "max diff");
  for (int part = 0; part < 3; ++part) {
    double lower = 0;
    for (int k = 0; k < bands; ++k) {
      const Band& b = parts[std::size_t(part)][std::size_t(k)];
      char label[64];
      if (std::isfinite(band_edges[k]))
        std::snprintf(label, sizeof label, "%g-%g spacings", lower, band_edges[k]);
      else
        std::snprintf(label, sizeof label, "> %g spacings", lower);
      lower = band_edges[k];
      if (b.faces)
        std::printf("%-10s %-20s %9zu %10zu %10zu %9zu %11zu %10.2e\n", part_names[part], label,
                    b.faces, b.identical, b.rounding, b.larger, b.free_differs, b.max_difference);
    }
  }
  return 0;
}

int main(int argc, char** argv) {
#if defined(__linux__) && defined(__GLIBC__)
  // The malloc settings of tspline (src/tspline/main.cpp: huge pages, a fixed mmap
  // threshold), so that the peaks compare with the tool's; glibc reads them at start-up.
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables == nullptr || std::string(tunables).find("glibc.malloc.") == std::string::npos) {
    const std::string value = std::string(tunables ? tunables : "") + (tunables ? ":" : "") +
                              "glibc.malloc.hugetlb=1:glibc.malloc.mmap_threshold=4194304:"
                              "glibc.malloc.trim_threshold=33554432";
    if (setenv("GLIBC_TUNABLES", value.c_str(), 1) == 0)
      execv("/proc/self/exe", argv);
  }
#endif
  Options o;
  bool parsed = false;
  try {
    parsed = parse(argc, argv, o);
  } catch (const std::exception&) { // std::stod and friends on a malformed number
  }
  if (!parsed) {
    std::cerr << "usage: tile_simulation [--n N] [--tiles T] [--halo SPACINGS] [--rings R] "
                 "[--retries K] [--fit adaptive|local] [--seed S] [--work DIR]\n";
    return 2;
  }
  try {
    return simulate(o);
  } catch (const std::exception& e) {
    std::cerr << "tile_simulation: " << e.what() << "\n";
    return 1;
  }
}
