// The compiled core of the Python module tspline (tspline._core): the library's splines
// behind one abstract class, numpy arrays in and out. The scipy-shaped API (argument
// checking, query shapes, fill_value) is python/tspline/__init__.py. One translation unit:
// the CGAL templates are instantiated once, for double and for exact rationals.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangular_spline/Blending/Mesh_blending_surface.h>
#include <CGAL/Triangular_spline/Comparators/PN_triangles.h>
#include <CGAL/Triangular_spline/Domain/Domain_locator.h>
#include <CGAL/Triangular_spline/Domain/delaunay_domain.h>
#include <CGAL/Triangular_spline/IO/spline_file.h>
#include <CGAL/Triangular_spline/IO/surface_file.h>
#include <CGAL/Triangular_spline/Mann/mann_interpolant.h>
#include <CGAL/Triangular_spline/Xu/Pseudo_AG1_surface.h>
#include <CGAL/Triangular_spline/Xu/Spline_space.h>
#include <CGAL/Triangular_spline/Xu/make_c1_quintic_spline.h>
#include <CGAL/Triangular_spline/Xu/pseudo_AG1_certificate.h>
#include <CGAL/Triangular_spline/Xu/thesis_polyhedra.h>
#include <CGAL/Triangular_spline/certify.h>
#include <CGAL/Triangular_spline/closed_surface.h>
#include <CGAL/Triangular_spline/evaluate.h>
#include <CGAL/Triangular_spline/exceptions.h>

#include "render/scene.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace py = pybind11;
namespace TS = CGAL::Triangular_spline;
namespace TSP = CGAL::Triangular_spline::parameters;
namespace render = tspline::render;

namespace {

using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;

using Points = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Queries are evaluated in chunks: bounds the jets held at once for 10^6-point queries.
constexpr std::size_t chunk_size = std::size_t(1) << 16;
// Values alone hold 24 bytes a query: larger chunks, so that queries in no spatial order
// are sorted by bucket over more of them (10^6 random queries: 2.7 M/s in chunks of 2^16).
constexpr std::size_t value_chunk_size = std::size_t(1) << 20;

// The rows of an (n, columns) array, checked (the Python layer reshapes; this is the guard).
const double* rows(const Points& a, py::ssize_t columns, const char* what, std::size_t& n) {
  if (a.ndim() != 2 || a.shape(1) != columns)
    throw TS::Invalid_input(std::string(what) + ": expected an array of shape (n, " +
                            std::to_string(columns) + ")");
  n = static_cast<std::size_t>(a.shape(0));
  return a.data();
}

template <class FT>
FT power_of_two(int exponent) {
  return exponent >= 0 ? FT(std::ldexp(1.0, exponent)) : FT(1) / FT(std::ldexp(1.0, -exponent));
}

// rescale=True: the power of two that brings the extent in y closest to the extent in x, as
// `tspline c1 --rescale` (exact in double and in rationals, so the spline is moved back onto
// the data's own points exactly).
int rescale_exponent(const double* xy, std::size_t n) {
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
  for (std::size_t i = 0; i < n; ++i) {
    x0 = (std::min)(x0, xy[2 * i]);
    x1 = (std::max)(x1, xy[2 * i]);
    y0 = (std::min)(y0, xy[2 * i + 1]);
    y1 = (std::max)(y1, xy[2 * i + 1]);
  }
  if (!(x1 > x0) || !(y1 > y0))
    return 0; // degenerate data: the domain builder says why
  return static_cast<int>(std::lround(std::log2((x1 - x0) / (y1 - y0))));
}

template <class K>
TS::Planar_domain<K> scaled_y(const TS::Planar_domain<K>& domain, int exponent) {
  const typename K::FT factor = power_of_two<typename K::FT>(exponent);
  std::vector<typename K::Point_2> points;
  points.reserve(domain.number_of_vertices());
  for (const auto& p : domain.points())
    points.emplace_back(p.x(), p.y() * factor);
  return TS::Planar_domain<K>(std::move(points), domain.faces());
}

TS::Fit parse_fit(const std::string& fit) {
  if (fit == "adaptive")
    return TS::Fit::ADAPTIVE;
  if (fit == "local")
    return TS::Fit::LOCAL_POLYNOMIAL;
  if (fit == "energy")
    return TS::Fit::MINIMAL_ENERGY;
  if (fit == "lsq")
    return TS::Fit::LEAST_SQUARES;
  if (fit == "tangent")
    return TS::Fit::TANGENT_PLANES;
  if (fit == "interpolate")
    return TS::Fit::INTERPOLATE;
  if (fit == "approximate")
    return TS::Fit::APPROXIMATE;
  throw TS::Invalid_input("fit must be adaptive, local, energy, lsq, tangent, interpolate or "
                          "approximate, not '" +
                          fit + "'");
}

TS::Outside parse_outside(const std::string& outside) {
  if (outside == "nan")
    return TS::Outside::NO_VALUE;
  if (outside == "nearest")
    return TS::Outside::NEAREST;
  if (outside == "linear")
    return TS::Outside::LINEAR;
  throw TS::Invalid_input("outside must be nan, nearest or linear, not '" + outside + "'");
}

// tspline.render: the options of `tspline render`, from the keywords the Python layer passes
// (checked there for types; the renderer checks the ranges with the CLI's messages).
render::Options render_options(const py::dict& o) {
  render::Options options;
  try {
    options.mode = render::parse_mode(o["mode"].cast<std::string>());
  } catch (const std::invalid_argument&) {
    throw TS::Invalid_input("mode must be shaded, curvature, isophotes, net or jump, not '" +
                            o["mode"].cast<std::string>() + "'");
  }
  options.width = o["width"].cast<int>();
  options.height = o["height"].cast<int>();
  options.azimuth = o["azimuth"].cast<double>();
  options.elevation = o["elevation"].cast<double>();
  options.perspective = o["perspective"].cast<bool>();
  if (!o["light"].is_none())
    options.light = o["light"].cast<render::Vector>();
  options.bands = o["bands"].cast<int>();
  if (!o["range"].is_none()) {
    const double range = o["range"].cast<double>();
    if (!(range > 0) || !std::isfinite(range))
      throw TS::Invalid_input("range must be a finite number > 0");
    options.curvature_range = range;
    options.jump_range = range;
  }
  options.supersampling = o["samples"].cast<int>();
  options.legend = o["legend"].cast<bool>();
  return options;
}

std::optional<int> render_levels(const py::dict& o) {
  if (o["levels"].is_none())
    return std::nullopt;
  const int levels = o["levels"].cast<int>();
  if (levels < 0 || levels > 8)
    throw TS::Invalid_input("levels must be between 0 and 8, not " + std::to_string(levels));
  return levels;
}

// The picture as a PNG file (the path returned) or, without a path, an (H, W, 3) uint8 array
// that owns the rasteriser's pixels (no copy).
py::object image_result(render::Image image, const std::optional<std::string>& output) {
  if (output) {
    py::gil_scoped_release release;
    render::write_png(*output, image);
  }
  if (output)
    return py::str(*output);
  auto* pixels = new std::vector<std::uint8_t>(std::move(image.pixels));
  py::capsule owner(pixels, [](void* p) { delete static_cast<std::vector<std::uint8_t>*>(p); });
  return py::array_t<std::uint8_t>(
      {py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(3)}, pixels->data(), owner);
}

// tspline.render of a file, as `tspline render --input path` draws it.
py::object render_file(const std::string& path, const std::optional<std::string>& output,
                       const py::dict& o) {
  const render::Options options = render_options(o);
  const std::optional<int> levels = render_levels(o);
  render::Image image;
  {
    py::gil_scoped_release release;
    render::Progress quiet(false);
    const render::Scene scene = render::load_scene(path, options.mode, levels, quiet);
    image = render::render_scene(scene, options);
  }
  return image_result(std::move(image), output);
}

// What the C1 fit was asked for: with_values() refits with the same settings.
struct Fit_settings {
  std::string fit = "adaptive";
  int degree = 5;
  std::string degree_selection = "cv";
  double smoothing = 0;
  std::optional<double> tension; // unset: the fit's default
  int y_exponent = 0;            // rescale: the domain's y is the data's times 2^y_exponent
};

// The Python-visible spline: any network of the library with its locator.
class Spline {
public:
  virtual ~Spline() = default;
  // (n, 1), (n, 3) or (n, 6): value; gradient; Hessian (xx, xy, yy). NaN where undefined.
  virtual py::array_t<double> evaluate(const Points& xi, int order,
                                       const std::string& outside) const = 0;
  virtual py::dict certify(std::optional<double> tolerance) const = 0;
  virtual void save(const std::string& path) const = 0;
  virtual std::shared_ptr<Spline> with_values(const Points& values,
                                              const std::optional<Points>& gradients) const = 0;
  virtual py::dict dimension(bool rational_fallback) const = 0;
  virtual py::dict info() const = 0;
  virtual py::array_t<double> points() const = 0;
  virtual py::array_t<std::int64_t> triangles() const = 0;
  virtual bool exact() const = 0;
  virtual int degree() const = 0;
  virtual std::string kind() const = 0;
  virtual py::object free_parameters() const = 0;
  // tspline.render: the tessellated network drawn as `tspline render` draws its .spline file
  virtual py::object render(const std::optional<std::string>& output,
                            const py::dict& options) const = 0;
};

// A network over a domain, the locator on (a copy of) that domain, and for each domain vertex
// the index of its input point (Delaunay numbers the vertices its own way).
template <class K, class Network>
class Spline_impl : public Spline {
public:
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  using Locator = TS::Domain_locator<K>;

  Spline_impl(std::shared_ptr<const Network> network, std::shared_ptr<const Locator> locator,
              std::shared_ptr<const std::vector<std::size_t>> input_index, std::string kind,
              Fit_settings settings = {}, py::dict info = {})
      : m_network(std::move(network)), m_locator(std::move(locator)),
        m_input_index(std::move(input_index)), m_kind(std::move(kind)),
        m_settings(std::move(settings)), m_info(std::move(info)) {}

  // A locator on the network's own domain; it keeps the network alive.
  static std::shared_ptr<const Locator> make_locator(const std::shared_ptr<const Network>& n) {
    return std::shared_ptr<const Locator>(new Locator(n->domain()),
                                          [n](const Locator* l) { delete l; });
  }

  py::array_t<double> evaluate(const Points& xi, int order,
                               const std::string& outside_name) const override {
    if (order < 0 || order > 2)
      throw TS::Invalid_input("derivative order must be 0, 1 or 2, not " + std::to_string(order));
    const TS::Outside outside = parse_outside(outside_name);
    std::size_t n = 0;
    const double* q = rows(xi, 2, "query points", n);
    const py::ssize_t columns = order == 0 ? 1 : order == 1 ? 3 : 6;
    py::array_t<double> result({static_cast<py::ssize_t>(n), columns});
    double* out = result.mutable_data();
    {
      py::gil_scoped_release release;
      const double nan = std::numeric_limits<double>::quiet_NaN();
      std::vector<Point_2> points;
      const bool values_only = order == 0 && outside == TS::Outside::NO_VALUE;
      const std::size_t chunk = values_only ? value_chunk_size : chunk_size;
      for (std::size_t begin = 0; begin < n; begin += chunk) {
        const std::size_t end = (std::min)(n, begin + chunk);
        points.clear();
        for (std::size_t i = begin; i < end; ++i)
          points.emplace_back(q[2 * i], q[2 * i + 1]);
        double* row = out + begin * static_cast<std::size_t>(columns);
        if (values_only) {
          // values only: the call `tspline c1 --query` makes
          const std::vector<double> values =
              TS::evaluate_functional(*m_network, *m_locator, points);
          std::copy(values.begin(), values.end(), row);
          continue;
        }
        const auto jets = TS::evaluate_jets(*m_network, *m_locator, points, outside, order);
        for (const auto& jet : jets) {
          if (!jet) {
            std::fill(row, row + columns, nan);
          } else {
            row[0] = CGAL::to_double(jet->value);
            if (order >= 1) {
              row[1] = CGAL::to_double(jet->gradient[0]);
              row[2] = CGAL::to_double(jet->gradient[1]);
            }
            if (order >= 2)
              for (int k = 0; k < 3; ++k)
                row[3 + k] = CGAL::to_double(jet->hessian[std::size_t(k)]);
          }
          row += columns;
        }
      }
    }
    return result;
  }

  py::dict certify(std::optional<double> tolerance) const override {
    TS::Continuity_certificate c;
    double used = 0;
    {
      py::gil_scoped_release release;
      if (tolerance) {
        used = *tolerance;
      } else if (!exact()) {
        // double builds: round-off accepted up to 1e-10 of the largest control value, as
        // `tspline c1` does
        double scale = 1;
        for (std::uint32_t f = 0; f < m_network->domain().number_of_faces(); ++f) {
          // binds to a stored patch, or extends the life of a computed one (C1 views)
          const auto& patch = m_network->patch(f);
          for (const FT& v : patch.control_points())
            scale = (std::max)(scale, std::abs(CGAL::to_double(v)));
        }
        used = 1e-10 * scale;
      }
      if (!(used >= 0) || !std::isfinite(used))
        throw TS::Invalid_input("tolerance must be a finite number >= 0");
      c = TS::certify_continuity(*m_network, 1, TSP::residual_tolerance(used));
    }
    py::dict d;
    d["verdict"] = TS::verdict_name(c.verdict);
    d["proof"] = c.verdict == TS::Certificate_verdict::PROOF;
    d["certified"] = c.certified;
    d["exact"] = c.exact;
    d["order"] = c.order;
    d["tolerance"] = c.tolerance;
    d["max_residual"] = c.max_residual;
    d["max_residual_log10"] = c.max_residual_log10;
    d["lowest_order"] = c.lowest_order;
    d["interior_edges"] = c.interior_edges;
    d["failed_edges"] = c.failed_edges;
    d["nonzero_edges"] = c.nonzero_edges;
    const py::ssize_t E = static_cast<py::ssize_t>(c.edges.size());
    py::array_t<std::int64_t> edge(E), vertices({E, py::ssize_t(2)});
    py::array_t<std::int64_t> achieved(E);
    py::array_t<bool> holds(E), zero(E);
    py::array_t<double> residual(E), residual_log10(E);
    for (py::ssize_t i = 0; i < E; ++i) {
      const TS::Edge_certificate& e = c.edges[std::size_t(i)];
      edge.mutable_at(i) = e.edge;
      vertices.mutable_at(i, 0) = static_cast<std::int64_t>(input_vertex(e.vertices[0]));
      vertices.mutable_at(i, 1) = static_cast<std::int64_t>(input_vertex(e.vertices[1]));
      achieved.mutable_at(i) = e.achieved_order;
      holds.mutable_at(i) = e.holds;
      zero.mutable_at(i) = e.zero;
      residual.mutable_at(i) = e.residual;
      residual_log10.mutable_at(i) = e.residual_log10;
    }
    py::dict edges;
    edges["edge"] = edge;
    edges["vertices"] = vertices;
    edges["achieved_order"] = achieved;
    edges["c1"] = holds;
    edges["zero"] = zero;
    edges["residual"] = residual;
    edges["residual_log10"] = residual_log10;
    d["edges"] = edges;
    return d;
  }

  void save(const std::string& path) const override {
    py::gil_scoped_release release;
    std::ofstream file(path);
    if (!file)
      throw std::runtime_error("cannot write '" + path + "'");
    TS::write_spline_file(file, *m_network);
    file.close();
    if (!file)
      throw std::runtime_error("writing '" + path + "' failed");
  }

  std::shared_ptr<Spline> with_values(const Points& values,
                                      const std::optional<Points>& gradients) const override {
    if constexpr (std::is_same_v<Network, TS::C1_quintic_spline<K>>) {
      const std::size_t V = m_network->domain().number_of_vertices();
      std::vector<FT> z;
      std::vector<std::array<FT, 2>> g;
      by_vertex(values, gradients, V, z, g);
      std::shared_ptr<Network> copy;
      {
        py::gil_scoped_release release;
        // The plan (frames, rules) is the domain's: only the fit and propagation run again.
        copy = std::make_shared<Network>(*m_network);
        if (m_settings.y_exponent != 0)
          copy->map_domain(scaled_y(copy->domain(), m_settings.y_exponent));
        TS::fit_vertex_data(*copy, z, parse_fit(m_settings.fit), m_settings.degree,
                            m_settings.degree_selection == "largest"
                                ? TS::Degree_selection::LARGEST
                                : TS::Degree_selection::CROSS_VALIDATION,
                            m_settings.smoothing, g, m_settings.tension);
        if (m_settings.y_exponent != 0)
          copy->map_domain(scaled_y(copy->domain(), -m_settings.y_exponent));
      }
      return std::make_shared<Spline_impl>(copy, m_locator, m_input_index, m_kind, m_settings,
                                           m_info);
    } else {
      (void)values;
      (void)gradients;
      throw TS::Invalid_input("with_values() needs a spline built by C1Interpolator (a " + m_kind +
                              " spline does not know its fit)");
    }
  }

  py::dict dimension(bool rational_fallback) const override {
    py::dict d;
    const auto& domain = m_network->domain();
    const std::optional<long long> morgan_scott = TS::morgan_scott_dimension(domain);
    d["morgan_scott"] = morgan_scott ? py::object(py::int_(*morgan_scott)) : py::object(py::none());
    // Proven by two bounds over the exact domain (the checked plan below, a modular rank
    // above), as `tspline c1 --dimension` does; the rational rank only when asked.
    TS::Dimension_certificate certificate;
    {
      py::gil_scoped_release release;
      certificate = TS::spline_dimension(domain, rational_fallback);
    }
    d["dimension"] = certificate.dimension ? py::object(py::int_(*certificate.dimension))
                                           : py::object(py::none());
    d["proven"] = certificate.dimension.has_value();
    d["lower_bound"] = certificate.free_parameters;
    d["lower_bound_proven"] = certificate.lower_bound_proven;
    d["upper_bound"] = certificate.upper_bound;
    d["prime"] = certificate.prime;
    d["primes_tried"] = certificate.primes_tried;
    d["rational_rank"] = certificate.rational_rank;
    d["free_parameters"] = free_parameters();
    return d;
  }

  py::dict info() const override {
    py::dict d = m_info.attr("copy")();
    const auto& domain = m_network->domain();
    d["vertices"] = domain.number_of_vertices();
    d["faces"] = domain.number_of_faces();
    d["interior_edges"] = domain.number_of_interior_edges();
    d["boundary_edges"] = domain.number_of_boundary_edges();
    d["boundary_loops"] = domain.number_of_boundary_loops();
    if constexpr (std::is_same_v<Network, TS::C1_quintic_spline<K>>) {
      d["fit"] = m_settings.fit;
      d["singular_vertices"] = m_network->singular_vertices().size();
      d["degenerate_frames"] = m_network->degenerate_frames().size();
      d["max_propagation_weight"] = m_network->max_propagation_weight();
      d["propagation_amplification"] = m_network->propagation_amplification();
      d["near_singular_vertices"] = m_network->near_singular_vertices().size();
      d["plan_rounds"] = m_network->plan_rounds();
      if (m_settings.y_exponent != 0)
        d["rescale_y_factor"] = std::ldexp(1.0, m_settings.y_exponent);
    }
    return d;
  }

  py::array_t<double> points() const override {
    const auto& domain = m_network->domain();
    const py::ssize_t V = static_cast<py::ssize_t>(domain.number_of_vertices());
    py::array_t<double> result({V, py::ssize_t(2)});
    auto r = result.template mutable_unchecked<2>();
    for (py::ssize_t v = 0; v < V; ++v) {
      const Point_2& p = domain.point(static_cast<std::uint32_t>(v));
      const std::size_t i = input_vertex(static_cast<std::uint32_t>(v));
      r(py::ssize_t(i), 0) = CGAL::to_double(p.x());
      r(py::ssize_t(i), 1) = CGAL::to_double(p.y());
    }
    return result;
  }

  py::array_t<std::int64_t> triangles() const override {
    const auto& domain = m_network->domain();
    const py::ssize_t F = static_cast<py::ssize_t>(domain.number_of_faces());
    py::array_t<std::int64_t> result({F, py::ssize_t(3)});
    auto r = result.template mutable_unchecked<2>();
    for (py::ssize_t f = 0; f < F; ++f)
      for (py::ssize_t k = 0; k < 3; ++k)
        r(f, k) = static_cast<std::int64_t>(
            input_vertex(domain.face(static_cast<std::uint32_t>(f))[std::size_t(k)]));
    return result;
  }

  bool exact() const override { return CGAL::Algebraic_structure_traits<FT>::Is_exact::value; }

  int degree() const override {
    return m_network->domain().number_of_faces() == 0 ? 0 : m_network->patch(0).degree();
  }

  std::string kind() const override { return m_kind; }

  py::object free_parameters() const override {
    if constexpr (std::is_same_v<Network, TS::C1_quintic_spline<K>>)
      return py::int_(m_network->number_of_free_parameters());
    else
      return py::none();
  }

  py::object render(const std::optional<std::string>& output, const py::dict& o) const override {
    const render::Options options = render_options(o);
    const std::optional<int> levels = render_levels(o);
    if (options.mode == render::Mode::Jump)
      throw TS::Invalid_input("jump mode needs a closed surface (normal jumps across its edges); "
                              "a spline over a planar domain has none");
    render::Image image;
    {
      py::gil_scoped_release release;
      image =
          render::render_scene(render::network_scene(*m_network, options.mode, levels), options);
    }
    return image_result(std::move(image), output);
  }

private:
  std::size_t input_vertex(std::uint32_t v) const {
    return m_input_index ? (*m_input_index)[v] : std::size_t(v);
  }

  // Values (and gradients) given in input order, in domain vertex order.
  void by_vertex(const Points& values, const std::optional<Points>& gradients, std::size_t V,
                 std::vector<FT>& z, std::vector<std::array<FT, 2>>& g) const {
    std::size_t n = 0;
    const double* v = rows(values, 1, "values", n);
    if (n != V)
      throw TS::Invalid_input("values: " + std::to_string(n) + " values for " + std::to_string(V) +
                              " points");
    z.resize(V);
    for (std::uint32_t i = 0; i < V; ++i)
      z[i] = FT(v[input_vertex(i)]);
    if (!gradients)
      return;
    const double* d = rows(*gradients, 2, "gradients", n);
    if (n != V)
      throw TS::Invalid_input("gradients: " + std::to_string(n) + " gradients for " +
                              std::to_string(V) + " points");
    const FT y_factor = power_of_two<FT>(m_settings.y_exponent);
    g.resize(V);
    for (std::uint32_t i = 0; i < V; ++i) {
      const std::size_t k = input_vertex(i);
      // dz/dy' = dz/dy / 2^e in the rescaled domain
      g[i] = {{FT(d[2 * k]), FT(d[2 * k + 1]) / y_factor}};
    }
  }

  std::shared_ptr<const Network> m_network;
  std::shared_ptr<const Locator> m_locator;
  std::shared_ptr<const std::vector<std::size_t>> m_input_index;
  std::string m_kind;
  Fit_settings m_settings;
  py::dict m_info;
};

// The Delaunay domain of the points, its vertices' input indices, and the values in domain
// order. Points must be finite: the triangulation's predicates assume it.
template <class K>
struct Scattered_domain {
  TS::Planar_domain<K> domain;
  std::vector<typename K::FT> values;
  std::shared_ptr<std::vector<std::size_t>> input_index;
  std::size_t flat_hull_faces = 0; // flat triangles closing the hull, removed
};

template <class K>
Scattered_domain<K> scattered_domain(const double* xy, const double* z, std::size_t n,
                                     int y_exponent) {
  using FT = typename K::FT;
  TS::Scattered_data<K> data;
  data.points.reserve(n);
  data.values.reserve(n);
  const FT y_factor = power_of_two<FT>(y_exponent);
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(xy[2 * i]) || !std::isfinite(xy[2 * i + 1]))
      throw TS::Invalid_input("scattered data: point " + std::to_string(i) +
                              " has a non-finite coordinate");
    data.points.emplace_back(FT(xy[2 * i]), FT(xy[2 * i + 1]) * y_factor);
    data.values.push_back(FT(z[i]));
  }
  auto order = std::make_shared<std::vector<std::size_t>>();
  std::size_t flat = 0;
  auto [domain, values] = TS::delaunay_domain(data, order.get(), &flat);
  return {std::move(domain), std::move(values), std::move(order), flat};
}

template <class K>
std::shared_ptr<Spline> make_c1(const Points& points, const Points& values,
                                const std::optional<Points>& gradients, const Fit_settings& asked,
                                bool rescale) {
  using FT = typename K::FT;
  using Network = TS::C1_quintic_spline<K>;
  std::size_t n = 0, nz = 0;
  const double* xy = rows(points, 2, "points", n);
  const double* z = rows(values, 1, "values", nz);
  if (nz != n)
    throw TS::Invalid_input("scattered data: " + std::to_string(n) + " points but " +
                            std::to_string(nz) + " values");
  std::size_t ng = 0;
  const double* dz = gradients ? rows(*gradients, 2, "gradients", ng) : nullptr;
  if (gradients && ng != n)
    throw TS::Invalid_input("gradients: " + std::to_string(ng) + " gradients for " +
                            std::to_string(n) + " points");
  const TS::Fit fit = parse_fit(asked.fit);
  Fit_settings settings = asked;
  // the tension the fit uses: the one asked for, else the library's default
  const double tension = asked.tension              ? *asked.tension
                         : fit == TS::Fit::ADAPTIVE ? TS::internal::adaptive_tension
                                                    : 0.0;
  std::shared_ptr<Network> spline;
  std::shared_ptr<std::vector<std::size_t>> order;
  TS::Fit_statistics statistics;
  std::size_t flat_hull_faces = 0;
  {
    py::gil_scoped_release release;
    settings.y_exponent = rescale ? rescale_exponent(xy, n) : 0;
    Scattered_domain<K> input = scattered_domain<K>(xy, z, n, settings.y_exponent);
    order = input.input_index;
    flat_hull_faces = input.flat_hull_faces;
    std::vector<std::array<FT, 2>> g;
    if (dz) {
      const FT y_factor = power_of_two<FT>(settings.y_exponent);
      for (std::size_t k : *order)
        g.push_back({{FT(dz[2 * k]), FT(dz[2 * k + 1]) / y_factor}});
    }
    const TS::Degree_selection selection = settings.degree_selection == "largest"
                                               ? TS::Degree_selection::LARGEST
                                               : TS::Degree_selection::CROSS_VALIDATION;
    spline = std::make_shared<Network>(TS::make_c1_quintic_spline(
        std::move(input.domain), input.values,
        TSP::data_fit(
            fit, TSP::local_degree(
                     settings.degree,
                     TSP::degree_selection(
                         selection,
                         TSP::smoothing(
                             settings.smoothing,
                             TSP::tension(tension, TSP::vertex_gradients(
                                                       g, TSP::fit_statistics(statistics)))))))));
    // Fitted in rescaled coordinates: back onto the data's own points (exact).
    if (settings.y_exponent != 0)
      spline->map_domain(scaled_y(spline->domain(), -settings.y_exponent));
  }
  py::dict info;
  info["flat_hull_faces_removed"] = flat_hull_faces;
  info["vertices_by_degree"] = statistics.vertices_by_degree;
  info["vertices_beyond_reach"] = statistics.vertices_beyond_reach;
  if (fit == TS::Fit::ADAPTIVE) {
    info["vertices_trusted"] = statistics.vertices_by_trust[0];
    info["vertices_blended"] = statistics.vertices_by_trust[1];
    info["vertices_minimal_energy"] = statistics.vertices_by_trust[2];
    info["energy_skipped"] = statistics.energy_skipped;
  }
  if (fit == TS::Fit::ADAPTIVE || fit == TS::Fit::MINIMAL_ENERGY)
    info["tension"] = tension;
  if (statistics.solver_sweeps > 0) {
    py::dict solver;
    solver["method"] = statistics.solver_method;
    solver["sweeps"] = statistics.solver_sweeps;
    solver["windows_per_sweep"] = statistics.solver_windows;
    solver["window_solves"] = statistics.solver_window_solves;
    solver["iterations"] = statistics.solver_iterations;
    solver["last_change"] = statistics.solver_last_change;
    solver["converged"] = statistics.solver_converged;
    info["solver"] = solver;
  }
  std::shared_ptr<const Network> network = spline;
  auto locator = Spline_impl<K, Network>::make_locator(network);
  return std::make_shared<Spline_impl<K, Network>>(network, locator, order, "c1", settings, info);
}

template <class K>
std::shared_ptr<Spline> make_mann(const Points& points, const Points& values, int degree) {
  using Network = TS::Mann_interpolant<K>;
  std::size_t n = 0, nz = 0;
  const double* xy = rows(points, 2, "points", n);
  const double* z = rows(values, 1, "values", nz);
  if (nz != n)
    throw TS::Invalid_input("scattered data: " + std::to_string(n) + " points but " +
                            std::to_string(nz) + " values");
  if (degree < 1 || degree > 13)
    throw TS::Invalid_input("Mann interpolant: degree must be between 1 and 13, not " +
                            std::to_string(degree));
  std::shared_ptr<const Network> network;
  std::shared_ptr<std::vector<std::size_t>> order;
  int continuity = 0;
  {
    py::gil_scoped_release release;
    Scattered_domain<K> input = scattered_domain<K>(xy, z, n, 0);
    order = input.input_index;
    for (const auto& v : input.values)
      if (!TS::is_finite_value(v))
        throw TS::Invalid_input("Mann interpolant: non-finite data value");
    const auto jets = TS::estimate_vertex_derivatives(input.domain, input.values,
                                                      TS::mann_derivative_order(degree));
    auto built = std::make_shared<Network>(TS::mann_interpolant(input.domain, jets, degree));
    continuity = built->continuity;
    network = built;
  }
  py::dict info;
  info["continuity"] = continuity;
  auto locator = Spline_impl<K, Network>::make_locator(network);
  return std::make_shared<Spline_impl<K, Network>>(network, locator, order, "mann", Fit_settings{},
                                                   info);
}

template <class K>
std::shared_ptr<Spline> load(const std::string& path) {
  using Network = TS::Spline_file<K, typename K::FT>;
  std::shared_ptr<const Network> network;
  {
    py::gil_scoped_release release;
    std::ifstream in(path);
    if (!in)
      throw TS::Invalid_input("cannot open '" + path + "'");
    if (TS::spline_file_dimension(in) == 3)
      throw TS::Invalid_input("'" + path +
                              "' holds a parametric spline (dimension 3): tspline.load needs a "
                              "functional spline z = f(x, y) (dimension 1)");
    network = std::make_shared<Network>(TS::read_spline_file<K, typename K::FT>(in, path));
  }
  auto locator = Spline_impl<K, Network>::make_locator(network);
  return std::make_shared<Spline_impl<K, Network>>(network, locator, nullptr, "file");
}

// Fang's blending surface of a polygon mesh (V, 3) + faces, tessellated with `resolution`
// segments per edge, as `tspline blend`: the triangles' vertices, the triangles, and per
// vertex the normal and the curvatures, per triangle its input face.
py::tuple blend(const py::array_t<double, py::array::c_style | py::array::forcecast>& vertices,
                const std::vector<std::vector<std::int64_t>>& faces, int order,
                const std::string& variant, const std::string& vertex_surface, int resolution) {
  using Point_3 = Fast::Point_3;
  using Mesh = CGAL::Surface_mesh<Point_3>;
  std::size_t n = 0;
  if (vertices.ndim() != 2 || vertices.shape(1) != 3)
    throw TS::Invalid_input("blend: vertices: expected an array of shape (n, 3)");
  n = static_cast<std::size_t>(vertices.shape(0));
  const double* xyz = vertices.data();
  TS::Mesh_blending_options options;
  options.order = order;
  if (variant == "basic")
    options.variant = TS::Blending_variant::BASIC;
  else if (variant == "vertex")
    options.variant = TS::Blending_variant::VERTEX_CONTINUITY;
  else if (variant == "open")
    options.variant = TS::Blending_variant::OPEN_SET;
  else
    throw TS::Invalid_input("blend: variant must be basic, vertex or open, not '" + variant + "'");
  if (vertex_surface == "least")
    options.vertex_surface = TS::Vertex_surface_method::LEAST;
  else if (vertex_surface == "lsq")
    options.vertex_surface = TS::Vertex_surface_method::LEAST_SQUARES;
  else if (vertex_surface == "normals")
    options.vertex_surface = TS::Vertex_surface_method::LEAST_SQUARES_NORMALS;
  else
    throw TS::Invalid_input("blend: vertex_surface must be least, lsq or normals, not '" +
                            vertex_surface + "'");
  Mesh out;
  {
    py::gil_scoped_release release;
    std::vector<Point_3> points;
    points.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(xyz[3 * i]) || !std::isfinite(xyz[3 * i + 1]) ||
          !std::isfinite(xyz[3 * i + 2]))
        throw TS::Invalid_input("blend: vertex " + std::to_string(i) +
                                " has a non-finite coordinate");
      points.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    }
    std::vector<std::vector<std::size_t>> polygons;
    polygons.reserve(faces.size());
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (faces[f].size() < 3)
        throw TS::Invalid_input("blend: face " + std::to_string(f) + " has fewer than 3 vertices");
      std::vector<std::size_t> polygon;
      for (std::int64_t v : faces[f]) {
        if (v < 0 || std::size_t(v) >= n)
          throw TS::Invalid_input("blend: face " + std::to_string(f) + " refers to vertex " +
                                  std::to_string(v) + ", not in [0, " + std::to_string(n) + ")");
        polygon.push_back(std::size_t(v));
      }
      polygons.push_back(std::move(polygon));
    }
    // the check of `tspline blend`: diagnose rather than repair
    if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
      throw TS::Invalid_input("blend: not a manifold, consistently oriented polygon mesh (an "
                              "edge has more than two faces, a vertex several umbrellas, or "
                              "neighbouring faces disagree on the orientation)");
    Mesh mesh;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    const TS::Mesh_blending_surface<Point_3> surface(mesh, options);
    surface.tessellate(out, resolution);
  }
  const py::ssize_t V = static_cast<py::ssize_t>(out.number_of_vertices());
  const py::ssize_t F = static_cast<py::ssize_t>(out.number_of_faces());
  py::array_t<double> points({V, py::ssize_t(3)}), normals({V, py::ssize_t(3)});
  py::array_t<double> gaussian(V), mean(V);
  py::array_t<std::int64_t> triangles({F, py::ssize_t(3)}), input_face(F);
  const auto normal_map = out.property_map<Mesh::Vertex_index, Fast::Vector_3>("v:normal");
  const auto k_map = out.property_map<Mesh::Vertex_index, double>("v:gaussian_curvature");
  const auto h_map = out.property_map<Mesh::Vertex_index, double>("v:mean_curvature");
  const auto face_map = out.property_map<Mesh::Face_index, std::size_t>("f:input_face");
  // the tessellation is built fresh: vertices and faces are numbered 0..n-1
  for (const auto v : out.vertices()) {
    const py::ssize_t i = static_cast<py::ssize_t>(v.idx());
    for (int c = 0; c < 3; ++c) {
      points.mutable_at(i, c) = out.point(v)[c];
      normals.mutable_at(i, c) = normal_map.second ? normal_map.first[v][c] : 0.0;
    }
    gaussian.mutable_at(i) = k_map.second ? k_map.first[v] : std::nan("");
    mean.mutable_at(i) = h_map.second ? h_map.first[v] : std::nan("");
  }
  for (const auto f : out.faces()) {
    const py::ssize_t i = static_cast<py::ssize_t>(f.idx());
    py::ssize_t c = 0;
    for (const auto v : CGAL::vertices_around_face(out.halfedge(f), out))
      if (c < 3)
        triangles.mutable_at(i, c++) = static_cast<std::int64_t>(v.idx());
    input_face.mutable_at(i) = face_map.second ? std::int64_t(face_map.first[f]) : -1;
  }
  py::dict properties;
  properties["normals"] = normals;
  properties["gaussian_curvature"] = gaussian;
  properties["mean_curvature"] = mean;
  properties["input_face"] = input_face;
  return py::make_tuple(points, triangles, properties);
}

// ---- Closed surfaces: pseudo-AG^1 (built or read from a file) and PN triangles --------------

using Faces = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

// A closed triangle mesh from (n, 3) vertices and (m, 3) faces, vertex i and face f keeping
// their numbers. Coordinates are checked before conversion (an exact number type cannot hold a
// NaN); the library checks the rest (closed, manifold, valence, zero areas) and orients.
template <class K>
CGAL::Surface_mesh<typename K::Point_3> mesh_from_arrays(const Points& vertices, const Faces& faces,
                                                         const std::string& context) {
  using Point_3 = typename K::Point_3;
  std::size_t n = 0, m = 0;
  const double* xyz = rows(vertices, 3, "vertices", n);
  if (faces.ndim() != 2 || faces.shape(1) != 3)
    throw TS::Invalid_input("faces: expected an array of shape (m, 3)");
  m = static_cast<std::size_t>(faces.shape(0));
  const std::int64_t* abc = faces.data();
  std::vector<Point_3> points;
  points.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t c = 0; c < 3; ++c)
      if (!std::isfinite(xyz[3 * i + c]))
        throw TS::Invalid_input(context + ": vertex " + std::to_string(i) +
                                " has a non-finite coordinate");
    points.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
  }
  std::vector<std::vector<std::size_t>> polygons(m);
  for (std::size_t f = 0; f < m; ++f) {
    for (std::size_t c = 0; c < 3; ++c) {
      const std::int64_t v = abc[3 * f + c];
      if (v < 0 || std::size_t(v) >= n)
        throw TS::Invalid_input(context + ": face " + std::to_string(f) + " refers to vertex " +
                                std::to_string(v) + ", not in [0, " + std::to_string(n) + ")");
      polygons[f].push_back(std::size_t(v));
    }
    if (polygons[f][0] == polygons[f][1] || polygons[f][1] == polygons[f][2] ||
        polygons[f][0] == polygons[f][2])
      throw TS::Invalid_input(context + ": face " + std::to_string(f) + " repeats a vertex");
  }
  // the check of `tspline pseudo-ag1 --input`: diagnose rather than repair
  if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
    throw TS::Invalid_input(context + ": not a manifold, consistently oriented triangle mesh (an "
                                      "edge has more than two faces, a vertex several umbrellas, "
                                      "or neighbouring faces disagree on the orientation)");
  CGAL::Surface_mesh<Point_3> mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return mesh;
}

// The double nearest to x: `CGAL::to_double` of GMP rationals truncates.
template <class FT>
double nearest(const FT& x) {
  if constexpr (std::is_same_v<FT, double>)
    return x;
  else
    return TS::internal::nearest_double(x);
}

template <class Mesh>
py::array_t<double> vertex_array(const Mesh& mesh) {
  py::array_t<double> result({static_cast<py::ssize_t>(mesh.number_of_vertices()), py::ssize_t(3)});
  auto r = result.template mutable_unchecked<2>();
  for (auto v : mesh.vertices())
    for (py::ssize_t c = 0; c < 3; ++c)
      r(py::ssize_t(v.idx()), c) = nearest(mesh.point(v)[int(c)]);
  return result;
}

// The faces in vertices_around_face(halfedge(f)) order: the corner order of the patches.
template <class Mesh>
py::array_t<std::int64_t> face_array(const Mesh& mesh) {
  py::array_t<std::int64_t> result(
      {static_cast<py::ssize_t>(mesh.number_of_faces()), py::ssize_t(3)});
  auto r = result.template mutable_unchecked<2>();
  for (auto f : mesh.faces()) {
    py::ssize_t c = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      if (c < 3)
        r(py::ssize_t(f.idx()), c++) = static_cast<std::int64_t>(v.idx());
  }
  return result;
}

template <class Surface>
struct Is_pseudo_AG1 : std::false_type {};
template <class K>
struct Is_pseudo_AG1<TS::Pseudo_AG1_surface<K>> : std::true_type {};

const char* corner_plane_normal_name(TS::Corner_plane_normal n) {
  return n == TS::Corner_plane_normal::CENTROID  ? "centroid"
         : n == TS::Corner_plane_normal::AVERAGE ? "average"
                                                 : "area";
}

// A piecewise polynomial surface over a closed mesh, one parametric patch per face.
class Closed_surface {
public:
  virtual ~Closed_surface() = default;
  virtual py::array_t<double> vertices() const = 0;
  virtual py::array_t<std::int64_t> faces() const = 0;
  virtual py::array_t<std::int64_t> edges() const = 0;
  virtual int degree() const = 0;
  virtual bool exact() const = 0;
  virtual std::string kind() const = 0;
  virtual py::array_t<double> control_nets() const = 0;
  virtual py::dict certify(double tolerance) const = 0;
  virtual py::dict measure(int samples, int levels, std::optional<bool> self_check) const = 0;
  virtual py::tuple tessellate(int levels, bool split_normals) const = 0;
  virtual py::tuple evaluate(const Faces& face_ids, const Points& weights) const = 0;
  virtual void save(const std::string& path) const = 0;
};

// What only a constructed pseudo-AG^1 surface knows.
class Pseudo_AG1 : public Closed_surface {
public:
  virtual py::dict info() const = 0;
  virtual py::dict options() const = 0;
  virtual py::dict corner_planes() const = 0;
  virtual py::dict edge_relations() const = 0;
};

template <class Surface, class Base>
class Closed_surface_impl : public Base {
public:
  using K = typename Surface::Geom_traits;
  using FT = typename K::FT;
  using Mesh = std::decay_t<decltype(std::declval<const Surface&>().mesh())>;

  Closed_surface_impl(std::shared_ptr<const Surface> surface, std::string kind)
      : m_surface(std::move(surface)), m_kind(std::move(kind)) {}

  py::array_t<double> vertices() const override { return vertex_array(mesh()); }
  py::array_t<std::int64_t> faces() const override { return face_array(mesh()); }
  py::array_t<std::int64_t> edges() const override {
    const Mesh& M = mesh();
    py::array_t<std::int64_t> result(
        {static_cast<py::ssize_t>(M.number_of_edges()), py::ssize_t(2)});
    auto r = result.template mutable_unchecked<2>();
    for (auto e : M.edges()) {
      const auto h = TS::canonical_halfedge(e, M);
      r(py::ssize_t(e.idx()), 0) = static_cast<std::int64_t>(M.source(h).idx());
      r(py::ssize_t(e.idx()), 1) = static_cast<std::int64_t>(M.target(h).idx());
    }
    return result;
  }
  int degree() const override { return m_surface->degree(); }
  bool exact() const override {
    if constexpr (Is_pseudo_AG1<Surface>::value)
      return m_surface->is_exact();
    else
      return CGAL::Algebraic_structure_traits<FT>::Is_exact::value;
  }
  std::string kind() const override { return m_kind; }

  py::array_t<double> control_nets() const override {
    const Mesh& M = mesh();
    const py::ssize_t F = static_cast<py::ssize_t>(M.number_of_faces());
    const py::ssize_t n = static_cast<py::ssize_t>(TS::number_of_control_points(degree()));
    py::array_t<double> result({F, n, py::ssize_t(3)});
    double* out = result.mutable_data();
    {
      py::gil_scoped_release release;
      for (auto f : M.faces()) {
        double* row = out + std::size_t(f.idx()) * std::size_t(n) * 3;
        for (const auto& p : m_surface->control_net(f))
          for (int c = 0; c < 3; ++c)
            *row++ = nearest(p[c]);
      }
    }
    return result;
  }

  py::dict certify(double tolerance) const override {
    if (!std::isfinite(tolerance))
      throw TS::Invalid_input("tolerance must be a finite number");
    TS::Pseudo_AG1_certificate c;
    std::vector<bool> determined;
    {
      py::gil_scoped_release release;
      if constexpr (Is_pseudo_AG1<Surface>::value) {
        c = TS::certify_pseudo_AG1(*m_surface, tolerance);
      } else {
        // from the control nets alone: relations and corner planes recovered from the file
        const TS::Pseudo_AG1_view<Surface> view(*m_surface);
        c = TS::certify_pseudo_AG1(view, tolerance);
        for (auto e : mesh().edges())
          determined.push_back(view.relation_determined(e));
      }
    }
    py::dict d;
    d["verdict"] = !c.pseudo_AG1() ? "failed" : c.exact ? "proof" : "within_tolerance";
    d["pseudo_ag1"] = c.pseudo_AG1();
    d["exact"] = c.exact;
    d["tolerance"] = c.tolerance;
    d["number_of_edges"] = c.edges;
    d["number_of_vertices"] = c.vertices;
    d["c0_edges"] = c.c0_edges;
    d["middle_edges"] = c.middle_edges;
    d["ag1_edges"] = c.ag1_edges;
    d["inadmissible_edges"] = c.inadmissible_edges;
    d["coplanar_vertices"] = c.coplanar_vertices;
    d["g1_vertices"] = c.g1_vertices;
    d["max_edge_residual"] = c.max_edge_residual;
    d["max_coplanarity"] = c.max_coplanarity;
    const py::ssize_t E = static_cast<py::ssize_t>(c.per_edge.size());
    py::array_t<bool> c0(E), middle(E), ag1(E), admissible(E), diamonds({E, py::ssize_t(5)});
    py::array_t<std::int64_t> join_order(E);
    py::array_t<double> residual(E), middle_residual(E);
    for (py::ssize_t i = 0; i < E; ++i) {
      const TS::Pseudo_AG1_edge_certificate& e = c.per_edge[std::size_t(i)];
      c0.mutable_at(i) = e.c0;
      middle.mutable_at(i) = e.middle;
      ag1.mutable_at(i) = e.ag1;
      admissible.mutable_at(i) = e.admissible;
      for (py::ssize_t k = 0; k < 5; ++k)
        diamonds.mutable_at(i, k) = e.diamonds[std::size_t(k)];
      join_order.mutable_at(i) = e.join_order;
      residual.mutable_at(i) = e.max_residual;
      middle_residual.mutable_at(i) = e.middle_residual;
    }
    py::dict edges;
    edges["vertices"] = this->edges();
    edges["c0"] = c0;
    edges["middle"] = middle;
    edges["ag1"] = ag1;
    edges["diamonds"] = diamonds;
    edges["admissible"] = admissible;
    edges["join_order"] = join_order;
    edges["residual"] = residual;
    edges["middle_residual"] = middle_residual;
    if (!determined.empty()) {
      py::array_t<bool> det(E);
      for (py::ssize_t i = 0; i < E; ++i)
        det.mutable_at(i) = determined[std::size_t(i)];
      edges["relation_determined"] = det;
    }
    d["edges"] = edges;
    return d;
  }

  py::dict measure(int samples, int levels, std::optional<bool> self_check) const override {
    if (levels < 0 || levels > 6)
      throw TS::Invalid_input("measure: levels must be in [0, 6], got " + std::to_string(levels));
    // as `tspline pseudo-ag1`: self-intersections only on tessellations of <= 400,000 triangles
    const bool check =
        self_check ? *self_check : (mesh().number_of_faces() << (2 * levels)) <= 400000;
    TS::Closed_surface_measures m;
    {
      py::gil_scoped_release release;
      const TS::Patch_sampler<Surface> sampler(*m_surface);
      m = TS::measure_closed_surface(mesh(), sampler, samples, levels, check);
    }
    py::dict d;
    d["edges"] = m.edges;
    d["samples_per_edge"] = m.samples_per_edge;
    d["max_jump_deg"] = m.max_jump_deg;
    d["mean_edge_max_jump_deg"] = m.mean_edge_max_jump_deg;
    d["mean_jump_deg"] = m.mean_jump_deg;
    d["rms_jump_deg"] = m.rms_jump_deg;
    d["p95_jump_deg"] = m.p95_jump_deg;
    d["max_unoriented_jump_deg"] = m.max_unoriented_jump_deg;
    d["vertex_max_jump_deg"] = m.vertex_max_jump_deg;
    d["input_mean_bend_deg"] = m.mean_input_bend_deg;
    d["volume"] = m.volume;
    d["input_volume"] = m.input_volume;
    d["volume_ratio"] = m.volume_ratio;
    d["hausdorff_rel"] = m.hausdorff_rel;
    d["rms_distance_rel"] = m.rms_distance_rel;
    d["inside_fraction"] = m.inside_fraction;
    d["folded_samples"] = m.folded_samples;
    d["singular_samples"] = m.singular_samples;
    d["self_intersecting"] = check ? py::object(py::bool_(m.self_intersecting)) : py::none();
    d["gaussian_min"] = m.gaussian_min;
    d["gaussian_max"] = m.gaussian_max;
    d["tessellation_faces"] = m.tessellation_faces;
    d["edge_max_jump_deg"] = py::array_t<double>(
        static_cast<py::ssize_t>(m.edge_max_jump_deg.size()), m.edge_max_jump_deg.data());
    d["edge_mean_jump_deg"] = py::array_t<double>(
        static_cast<py::ssize_t>(m.edge_mean_jump_deg.size()), m.edge_mean_jump_deg.data());
    return d;
  }

  py::tuple tessellate(int levels, bool split_normals) const override {
    TS::Closed_tessellation t;
    {
      py::gil_scoped_release release;
      const TS::Patch_sampler<Surface> sampler(*m_surface);
      t = TS::tessellate_closed_surface(mesh(), sampler, levels, split_normals);
    }
    const py::ssize_t V = static_cast<py::ssize_t>(t.mesh.number_of_vertices());
    py::array_t<double> normals({V, py::ssize_t(3)}), gaussian(V);
    for (py::ssize_t i = 0; i < V; ++i) {
      for (py::ssize_t c = 0; c < 3; ++c)
        normals.mutable_at(i, c) = t.normals[std::size_t(i)][std::size_t(c)];
      gaussian.mutable_at(i) = t.gaussian[std::size_t(i)];
    }
    return py::make_tuple(vertex_array(t.mesh), face_array(t.mesh), normals, gaussian);
  }

  py::tuple evaluate(const Faces& face_ids, const Points& weights) const override {
    const std::size_t F = mesh().number_of_faces();
    if (face_ids.ndim() != 1)
      throw TS::Invalid_input("face_ids: expected an array of shape (k,)");
    const std::size_t k = static_cast<std::size_t>(face_ids.shape(0));
    std::size_t nw = 0;
    const double* w = rows(weights, 3, "bary", nw);
    if (nw != k)
      throw TS::Invalid_input("evaluate: " + std::to_string(k) + " faces but " +
                              std::to_string(nw) + " rows of barycentric weights");
    const std::int64_t* ids = face_ids.data();
    py::array_t<double> points({static_cast<py::ssize_t>(k), py::ssize_t(3)});
    py::array_t<double> normals({static_cast<py::ssize_t>(k), py::ssize_t(3)});
    double* p = points.mutable_data();
    double* n = normals.mutable_data();
    {
      py::gil_scoped_release release;
      for (std::size_t i = 0; i < k; ++i) {
        if (ids[i] < 0 || std::size_t(ids[i]) >= F)
          throw TS::Invalid_input("evaluate: face " + std::to_string(ids[i]) + " not in [0, " +
                                  std::to_string(F) + ")");
        const double s = w[3 * i] + w[3 * i + 1] + w[3 * i + 2];
        if (!std::isfinite(s) || std::abs(s - 1) > 1e-9)
          throw TS::Invalid_input("evaluate: the barycentric weights of row " + std::to_string(i) +
                                  " must be finite and sum to 1");
      }
      // sorted by face: the sampler converts each patch once
      std::vector<std::size_t> order(k);
      for (std::size_t i = 0; i < k; ++i)
        order[i] = i;
      std::stable_sort(order.begin(), order.end(),
                       [ids](std::size_t a, std::size_t b) { return ids[a] < ids[b]; });
      const TS::Patch_sampler<Surface> sampler(*m_surface);
      for (std::size_t i : order) {
        const TS::Surface_sample s =
            sampler(typename Mesh::Face_index(typename Mesh::size_type(ids[i])),
                    std::array<double, 3>{{w[3 * i], w[3 * i + 1], w[3 * i + 2]}});
        for (std::size_t c = 0; c < 3; ++c) {
          p[3 * i + c] = s.point[c];
          n[3 * i + c] = s.regular ? s.normal[c] : std::numeric_limits<double>::quiet_NaN();
        }
      }
    }
    return py::make_tuple(points, normals);
  }

  void save(const std::string& path) const override {
    py::gil_scoped_release release;
    std::ofstream file(path);
    if (!file)
      throw std::runtime_error("cannot write '" + path + "'");
    TS::write_surface_file(file, *m_surface);
    file.close();
    if (!file)
      throw std::runtime_error("writing '" + path + "' failed");
  }

protected:
  const Mesh& mesh() const { return m_surface->mesh(); }
  std::shared_ptr<const Surface> m_surface;
  std::string m_kind;
};

template <class K>
class Pseudo_AG1_impl : public Closed_surface_impl<TS::Pseudo_AG1_surface<K>, Pseudo_AG1> {
  using Base = Closed_surface_impl<TS::Pseudo_AG1_surface<K>, Pseudo_AG1>;

public:
  Pseudo_AG1_impl(std::shared_ptr<const TS::Pseudo_AG1_surface<K>> surface, std::string preset)
      : Base(std::move(surface), "pseudo-AG1"), m_preset(std::move(preset)) {}

  py::dict info() const override {
    const TS::Pseudo_AG1_surface<K>& s = *this->m_surface;
    const auto& summary = s.mesh_summary();
    py::dict d;
    d["vertices"] = summary.vertices;
    d["edges"] = summary.edges;
    d["faces"] = summary.faces;
    d["components"] = summary.components.size();
    long euler = 0;
    py::list genus;
    for (const auto& c : summary.components) {
      euler += c.euler;
      genus.append(c.genus);
    }
    d["euler"] = euler;
    d["genus"] = genus; // per component
    d["reoriented"] = summary.reoriented;
    d["exact"] = s.is_exact();
    const auto f = s.flags();
    py::dict flags;
    f.for_each([&](const char* name, std::size_t count) { flags[name] = count; });
    d["flags"] = flags;
    return d;
  }

  py::dict options() const override {
    const TS::Pseudo_AG1_options& o = this->m_surface->options();
    py::dict d;
    d["preset"] = m_preset;
    d["normal"] = corner_plane_normal_name(o.normal);
    d["tau"] = o.plane_position;
    d["undulation_gain"] = o.undulation_gain;
    d["threshold_deg"] = o.undulation_threshold * 180 / CGAL_PI;
    d["placement"] = o.placement == TS::Star_placement::UMBRELLA ? "umbrella" : "projection";
    d["angles"] = o.angles == TS::Umbrella_angles::EQUAL ? "equal" : "proportional";
    d["lengths"] = o.lengths == TS::Umbrella_lengths::RIGID          ? "rigid"
                   : o.lengths == TS::Umbrella_lengths::PROPORTIONAL ? "proportional"
                                                                     : "equal";
    d["rotation"] =
        o.rotation == TS::Umbrella_rotation::LEAST_SQUARES ? "least-squares" : "first-star";
    d["recentering"] = o.recentering;
    d["star_scale"] = o.star_scale;
    d["shrink"] = o.automatic_shrinking ? "auto" : "none";
    d["offsets"] = py::make_tuple(o.offsets[0], o.offsets[1], o.offsets[2]);
    d["inner"] = o.inner == TS::Inner_placement::NORMAL_OFFSET ? "offset" : "cross-edge";
    d["edge_map"] = o.edge_map == TS::Edge_map::PARALLELOGRAM ? "parallelogram" : "averaged";
    d["flip"] = o.flips == TS::Flip_rule::SYMMETRIC     ? "symmetric"
                : o.flips == TS::Flip_rule::LARGER_FACE ? "larger-face"
                                                        : "lower-index";
    d["rational"] = o.is_rational();
    return d;
  }

  py::dict corner_planes() const override {
    const TS::Pseudo_AG1_surface<K>& s = *this->m_surface;
    const py::ssize_t V = static_cast<py::ssize_t>(s.mesh().number_of_vertices());
    py::array_t<double> corner({V, py::ssize_t(3)}), normal({V, py::ssize_t(3)});
    py::array_t<double> centroid({V, py::ssize_t(3)}), offset(V), dihedral(V), scale(V);
    py::array_t<bool> recentred(V), folded(V), equalised(V), fallback(V), inverted(V);
    py::list used;
    for (auto v : s.mesh().vertices()) {
      const py::ssize_t i = static_cast<py::ssize_t>(v.idx());
      const auto& p = s.corner_plane(v);
      const double length = std::sqrt(CGAL::to_double(p.normal.squared_length()));
      for (py::ssize_t c = 0; c < 3; ++c) {
        corner.mutable_at(i, c) = nearest(p.corner[int(c)]);
        normal.mutable_at(i, c) = CGAL::to_double(p.normal[int(c)]) / length;
        centroid.mutable_at(i, c) = nearest(p.centroid[int(c)]);
      }
      // H_v is along the unnormalized N_v: the signed distance of the plane from v
      offset.mutable_at(i) = CGAL::to_double(p.offset) / length;
      dihedral.mutable_at(i) = p.mean_dihedral * 180 / CGAL_PI;
      scale.mutable_at(i) = p.star_scale;
      recentred.mutable_at(i) = p.recentred;
      folded.mutable_at(i) = p.folded_projection;
      equalised.mutable_at(i) = p.equalised;
      fallback.mutable_at(i) = p.normal_fallback;
      inverted.mutable_at(i) = p.inverted_corner;
      used.append(corner_plane_normal_name(p.normal_used));
    }
    py::dict d;
    d["corner"] = corner;
    d["normal"] = normal;
    d["distance"] = offset;
    d["centroid"] = centroid;
    d["mean_dihedral_deg"] = dihedral;
    d["star_scale"] = scale;
    d["normal_used"] = used;
    d["recentred"] = recentred;
    d["folded_projection"] = folded;
    d["equalised"] = equalised;
    d["normal_fallback"] = fallback;
    d["inverted_corner"] = inverted;
    return d;
  }

  py::dict edge_relations() const override {
    const TS::Pseudo_AG1_surface<K>& s = *this->m_surface;
    const py::ssize_t E = static_cast<py::ssize_t>(s.mesh().number_of_edges());
    py::array_t<double> relation({E, py::ssize_t(3)}), end_r({E, py::ssize_t(3)});
    py::array_t<double> end_s({E, py::ssize_t(3)}), dihedral(E), dip(E);
    py::array_t<bool> r_valid(E), s_valid(E), averaged(E);
    for (auto e : s.mesh().edges()) {
      const py::ssize_t i = static_cast<py::ssize_t>(e.idx());
      const auto& R = s.edge_relation(e);
      for (py::ssize_t c = 0; c < 3; ++c) {
        relation.mutable_at(i, c) = nearest(R.relation[std::size_t(c)]);
        end_r.mutable_at(i, c) = nearest(R.end_r[std::size_t(c)]);
        end_s.mutable_at(i, c) = nearest(R.end_s[std::size_t(c)]);
      }
      r_valid.mutable_at(i) = R.end_r_valid;
      s_valid.mutable_at(i) = R.end_s_valid;
      averaged.mutable_at(i) = R.averaged_fallback;
      dihedral.mutable_at(i) = R.dihedral * 180 / CGAL_PI;
      dip.mutable_at(i) = s.dip(e);
    }
    py::dict d;
    d["vertices"] = this->edges();
    d["relation"] = relation;
    d["end_r"] = end_r;
    d["end_s"] = end_s;
    d["end_r_valid"] = r_valid;
    d["end_s_valid"] = s_valid;
    d["averaged_fallback"] = averaged;
    d["dihedral_deg"] = dihedral;
    d["dip"] = dip;
    return d;
  }

private:
  std::string m_preset;
};

template <class Enum>
Enum option_choice(const std::string& key, const py::handle& value,
                   const std::vector<std::pair<const char*, Enum>>& choices) {
  const std::string given = py::str(value);
  std::string names;
  for (const auto& [name, e] : choices) {
    if (given == name)
      return e;
    names += (names.empty() ? "" : ", ") + std::string(name);
  }
  throw TS::Invalid_input("pseudo-AG1: " + key + " must be one of " + names + ", not '" + given +
                          "'");
}

// The preset with the overrides of AG1.md §4.1 (the names of `tspline pseudo-ag1`'s options).
TS::Pseudo_AG1_options pseudo_AG1_options(const std::string& preset, const py::dict& overrides) {
  TS::Pseudo_AG1_options o = TS::pseudo_AG1_preset(preset);
  for (const auto& [k, value] : overrides) {
    const std::string key = py::str(k);
    auto number = [&]() {
      return py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>();
    };
    if (key == "normal")
      o.normal =
          option_choice<TS::Corner_plane_normal>(key, value,
                                                 {{"area", TS::Corner_plane_normal::AREA_WEIGHTED},
                                                  {"average", TS::Corner_plane_normal::AVERAGE},
                                                  {"centroid", TS::Corner_plane_normal::CENTROID}});
    else if (key == "tau")
      o.plane_position = number();
    else if (key == "undulation_gain")
      o.undulation_gain = number();
    else if (key == "threshold_deg")
      o.undulation_threshold = number() * CGAL_PI / 180;
    else if (key == "placement")
      o.placement =
          option_choice<TS::Star_placement>(key, value,
                                            {{"umbrella", TS::Star_placement::UMBRELLA},
                                             {"projection", TS::Star_placement::PROJECTION}});
    else if (key == "lengths")
      o.lengths =
          option_choice<TS::Umbrella_lengths>(key, value,
                                              {{"rigid", TS::Umbrella_lengths::RIGID},
                                               {"proportional", TS::Umbrella_lengths::PROPORTIONAL},
                                               {"equal", TS::Umbrella_lengths::EQUAL}});
    else if (key == "angles")
      o.angles =
          option_choice<TS::Umbrella_angles>(key, value,
                                             {{"proportional", TS::Umbrella_angles::PROPORTIONAL},
                                              {"equal", TS::Umbrella_angles::EQUAL}});
    else if (key == "rotation")
      o.rotation = option_choice<TS::Umbrella_rotation>(
          key, value,
          {{"least-squares", TS::Umbrella_rotation::LEAST_SQUARES},
           {"first-star", TS::Umbrella_rotation::FIRST_STAR}});
    else if (key == "recentering")
      o.recentering = py::bool_(py::reinterpret_borrow<py::object>(value));
    else if (key == "star_scale")
      o.star_scale = number();
    else if (key == "shrink")
      o.automatic_shrinking = option_choice<bool>(key, value, {{"none", false}, {"auto", true}});
    else if (key == "offsets") {
      const auto v = py::reinterpret_borrow<py::object>(value).cast<std::vector<double>>();
      if (v.size() != 3)
        throw TS::Invalid_input("pseudo-AG1: offsets must be three numbers (stars, inner, flips)");
      o.offsets = {{v[0], v[1], v[2]}};
    } else if (key == "inner")
      o.inner = option_choice<TS::Inner_placement>(
          key, value,
          {{"offset", TS::Inner_placement::NORMAL_OFFSET},
           {"cross-edge", TS::Inner_placement::CROSS_EDGE_PLANES}});
    else if (key == "edge_map")
      o.edge_map = option_choice<TS::Edge_map>(key, value,
                                               {{"parallelogram", TS::Edge_map::PARALLELOGRAM},
                                                {"averaged", TS::Edge_map::AVERAGED_DIAMOND}});
    else if (key == "flip")
      o.flips = option_choice<TS::Flip_rule>(key, value,
                                             {{"symmetric", TS::Flip_rule::SYMMETRIC},
                                              {"larger-face", TS::Flip_rule::LARGER_FACE},
                                              {"lower-index", TS::Flip_rule::LOWER_INDEX_FACE}});
    else
      throw py::type_error("PseudoAG1Surface: unexpected keyword argument '" + key + "'");
  }
  return o;
}

template <class K>
std::shared_ptr<Pseudo_AG1> make_pseudo_AG1(const Points& vertices, const Faces& faces,
                                            const std::string& preset,
                                            const TS::Pseudo_AG1_options& options) {
  std::shared_ptr<const TS::Pseudo_AG1_surface<K>> surface;
  {
    py::gil_scoped_release release;
    const auto mesh = mesh_from_arrays<K>(vertices, faces, "pseudo-AG1");
    surface = std::make_shared<const TS::Pseudo_AG1_surface<K>>(mesh, options);
  }
  return std::make_shared<Pseudo_AG1_impl<K>>(surface, preset);
}

template <class K>
std::shared_ptr<Closed_surface> load_surface(const std::string& path) {
  std::shared_ptr<const TS::Surface_file<K>> file;
  {
    py::gil_scoped_release release;
    std::ifstream in(path);
    if (!in)
      throw TS::Invalid_input("cannot open '" + path + "'");
    file = std::make_shared<const TS::Surface_file<K>>(TS::read_surface_file<K>(in, path));
  }
  return std::make_shared<Closed_surface_impl<TS::Surface_file<K>, Closed_surface>>(file, "file");
}

// PN triangles (Vlachos et al. 2001) of a closed mesh, as a surface of cubic patches.
std::shared_ptr<Closed_surface> pn_triangles(const Points& vertices, const Faces& faces) {
  using File = TS::Surface_file<Fast>;
  std::shared_ptr<const File> file;
  {
    py::gil_scoped_release release;
    auto mesh = mesh_from_arrays<Fast>(vertices, faces, "PN triangles");
    TS::prepare_closed_triangle_mesh(mesh, "PN triangles");
    const auto patches = TS::pn_triangles<Fast>(mesh);
    std::vector<std::vector<Fast::Vector_3>> nets;
    nets.reserve(patches.size());
    for (const auto& p : patches)
      nets.push_back(p.control_points());
    file = std::make_shared<const File>(std::move(mesh), 3, std::move(nets), false);
  }
  return std::make_shared<Closed_surface_impl<File, Closed_surface>>(file, "PN triangles");
}

py::tuple thesis_polyhedron(const std::string& name) {
  const auto mesh = TS::thesis_polyhedron<Fast>(name);
  return py::make_tuple(vertex_array(mesh), face_array(mesh));
}

} // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "The compiled core of tspline (use the tspline package, not this module).";
  py::class_<Spline, std::shared_ptr<Spline>>(m, "Spline")
      .def("evaluate", &Spline::evaluate, py::arg("xi"), py::arg("order") = 0,
           py::arg("outside") = "nan")
      .def("certify", &Spline::certify, py::arg("tolerance") = py::none())
      .def("save", &Spline::save, py::arg("path"))
      .def("with_values", &Spline::with_values, py::arg("values"),
           py::arg("gradients") = py::none())
      .def("dimension", &Spline::dimension, py::arg("rational_fallback") = false)
      .def("info", &Spline::info)
      .def("points", &Spline::points)
      .def("triangles", &Spline::triangles)
      .def_property_readonly("exact", &Spline::exact)
      .def_property_readonly("degree", &Spline::degree)
      .def_property_readonly("kind", &Spline::kind)
      .def_property_readonly("free_parameters", &Spline::free_parameters)
      .def("render", &Spline::render, py::arg("output"), py::arg("options"));
  m.def("render_file", &render_file, py::arg("path"), py::arg("output"), py::arg("options"));

  m.def(
      "c1",
      [](const Points& points, const Points& values, const std::optional<Points>& gradients,
         const std::string& fit, int degree, const std::string& degree_selection, double smoothing,
         std::optional<double> tension, bool rescale, bool exact) {
        Fit_settings settings{fit, degree, degree_selection, smoothing, tension, 0};
        return exact ? make_c1<Exact>(points, values, gradients, settings, rescale)
                     : make_c1<Fast>(points, values, gradients, settings, rescale);
      },
      py::arg("points"), py::arg("values"), py::arg("gradients"), py::arg("fit"), py::arg("degree"),
      py::arg("degree_selection"), py::arg("smoothing"), py::arg("tension"), py::arg("rescale"),
      py::arg("exact"));
  m.def(
      "mann",
      [](const Points& points, const Points& values, int degree, bool exact) {
        return exact ? make_mann<Exact>(points, values, degree)
                     : make_mann<Fast>(points, values, degree);
      },
      py::arg("points"), py::arg("values"), py::arg("degree"), py::arg("exact"));
  m.def(
      "load",
      [](const std::string& path, bool exact) {
        return exact ? load<Exact>(path) : load<Fast>(path);
      },
      py::arg("path"), py::arg("exact"));
  m.def("blend", &blend, py::arg("vertices"), py::arg("faces"), py::arg("order"),
        py::arg("variant"), py::arg("vertex_surface"), py::arg("resolution"));

  py::class_<Closed_surface, std::shared_ptr<Closed_surface>>(m, "ClosedSurface")
      .def("vertices", &Closed_surface::vertices)
      .def("faces", &Closed_surface::faces)
      .def("edges", &Closed_surface::edges)
      .def("control_nets", &Closed_surface::control_nets)
      .def("certify", &Closed_surface::certify, py::arg("tolerance"))
      .def("measure", &Closed_surface::measure, py::arg("samples"), py::arg("levels"),
           py::arg("self_intersections"))
      .def("tessellate", &Closed_surface::tessellate, py::arg("levels"), py::arg("split_normals"))
      .def("evaluate", &Closed_surface::evaluate, py::arg("face_ids"), py::arg("bary"))
      .def("save", &Closed_surface::save, py::arg("path"))
      .def_property_readonly("degree", &Closed_surface::degree)
      .def_property_readonly("exact", &Closed_surface::exact)
      .def_property_readonly("kind", &Closed_surface::kind);
  py::class_<Pseudo_AG1, Closed_surface, std::shared_ptr<Pseudo_AG1>>(m, "PseudoAG1")
      .def("info", &Pseudo_AG1::info)
      .def("options", &Pseudo_AG1::options)
      .def("corner_planes", &Pseudo_AG1::corner_planes)
      .def("edge_relations", &Pseudo_AG1::edge_relations);
  m.def(
      "pseudo_ag1",
      [](const Points& vertices, const Faces& faces, const std::string& preset, bool exact,
         const py::dict& overrides) -> std::shared_ptr<Pseudo_AG1> {
        const TS::Pseudo_AG1_options options = pseudo_AG1_options(preset, overrides);
        if (!exact)
          return make_pseudo_AG1<Fast>(vertices, faces, preset, options);
        if (!options.is_rational())
          throw TS::Invalid_input(
              "pseudo-AG1: exact=True needs rational options (projection placement, no offsets, "
              "undulation gain 0, area or centroid normals, offset inner points, no shrinking): "
              "use preset 'exact' or 'chapter5'");
        return make_pseudo_AG1<Exact>(vertices, faces, preset, options);
      },
      py::arg("vertices"), py::arg("faces"), py::arg("preset"), py::arg("exact"),
      py::arg("overrides"));
  m.def(
      "load_surface",
      [](const std::string& path, bool exact) {
        return exact ? load_surface<Exact>(path) : load_surface<Fast>(path);
      },
      py::arg("path"), py::arg("exact"));
  m.def("pn_triangles", &pn_triangles, py::arg("vertices"), py::arg("faces"));
  m.def("thesis_polyhedron", &thesis_polyhedron, py::arg("name"));
  m.def("thesis_polyhedron_names", &TS::thesis_polyhedron_names);
  m.attr("__version__") = TRIANGULAR_SPLINE_VERSION;
}
