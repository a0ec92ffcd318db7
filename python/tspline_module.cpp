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
#include <CGAL/Triangular_spline/Domain/Domain_locator.h>
#include <CGAL/Triangular_spline/Domain/delaunay_domain.h>
#include <CGAL/Triangular_spline/IO/spline_file.h>
#include <CGAL/Triangular_spline/Mann/mann_interpolant.h>
#include <CGAL/Triangular_spline/Xu/Spline_space.h>
#include <CGAL/Triangular_spline/Xu/make_c1_quintic_spline.h>
#include <CGAL/Triangular_spline/certify.h>
#include <CGAL/Triangular_spline/evaluate.h>
#include <CGAL/Triangular_spline/exceptions.h>

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

namespace {

using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;

using Points = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Queries are evaluated in chunks: bounds the jets held at once for 10^6-point queries.
constexpr std::size_t chunk_size = std::size_t(1) << 16;

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

// What the C1 fit was asked for: with_values() refits with the same settings.
struct Fit_settings {
  std::string fit = "adaptive";
  int degree = 5;
  std::string degree_selection = "cv";
  double smoothing = 0;
  int y_exponent = 0; // rescale: the domain's y is the data's times 2^y_exponent
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
  virtual py::dict dimension() const = 0;
  virtual py::dict info() const = 0;
  virtual py::array_t<double> points() const = 0;
  virtual py::array_t<std::int64_t> triangles() const = 0;
  virtual bool exact() const = 0;
  virtual int degree() const = 0;
  virtual std::string kind() const = 0;
  virtual py::object free_parameters() const = 0;
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
      for (std::size_t begin = 0; begin < n; begin += chunk_size) {
        const std::size_t end = (std::min)(n, begin + chunk_size);
        points.clear();
        for (std::size_t i = begin; i < end; ++i)
          points.emplace_back(q[2 * i], q[2 * i + 1]);
        double* row = out + begin * static_cast<std::size_t>(columns);
        if (order == 0 && outside == TS::Outside::NO_VALUE) {
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
                            m_settings.smoothing, g);
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

  py::dict dimension() const override {
    py::dict d;
    const auto& domain = m_network->domain();
    const std::optional<long long> morgan_scott = TS::morgan_scott_dimension(domain);
    d["morgan_scott"] = morgan_scott ? py::object(py::int_(*morgan_scott)) : py::object(py::none());
    TS::Dimension_bound bound;
    {
      py::gil_scoped_release release;
      bound = TS::spline_dimension_upper_bound(domain);
    }
    d["upper_bound"] = bound.upper_bound;
    d["prime"] = bound.prime;
    d["free_parameters"] = free_parameters();
    if constexpr (std::is_same_v<Network, TS::C1_quintic_spline<K>>)
      d["proven"] = bound.upper_bound == m_network->number_of_free_parameters();
    else
      d["proven"] = false;
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
  auto [domain, values] = TS::delaunay_domain(data, order.get());
  return {std::move(domain), std::move(values), std::move(order)};
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
  std::shared_ptr<Network> spline;
  std::shared_ptr<std::vector<std::size_t>> order;
  TS::Fit_statistics statistics;
  {
    py::gil_scoped_release release;
    settings.y_exponent = rescale ? rescale_exponent(xy, n) : 0;
    Scattered_domain<K> input = scattered_domain<K>(xy, z, n, settings.y_exponent);
    order = input.input_index;
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
                         selection, TSP::smoothing(settings.smoothing,
                                                   TSP::vertex_gradients(
                                                       g, TSP::fit_statistics(statistics))))))));
    // Fitted in rescaled coordinates: back onto the data's own points (exact).
    if (settings.y_exponent != 0)
      spline->map_domain(scaled_y(spline->domain(), -settings.y_exponent));
  }
  py::dict info;
  info["vertices_by_degree"] = statistics.vertices_by_degree;
  if (fit == TS::Fit::ADAPTIVE) {
    info["vertices_trusted"] = statistics.vertices_by_trust[0];
    info["vertices_blended"] = statistics.vertices_by_trust[1];
    info["vertices_minimal_energy"] = statistics.vertices_by_trust[2];
    info["energy_skipped"] = statistics.energy_skipped;
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
      .def("dimension", &Spline::dimension)
      .def("info", &Spline::info)
      .def("points", &Spline::points)
      .def("triangles", &Spline::triangles)
      .def_property_readonly("exact", &Spline::exact)
      .def_property_readonly("degree", &Spline::degree)
      .def_property_readonly("kind", &Spline::kind)
      .def_property_readonly("free_parameters", &Spline::free_parameters);

  m.def(
      "c1",
      [](const Points& points, const Points& values, const std::optional<Points>& gradients,
         const std::string& fit, int degree, const std::string& degree_selection, double smoothing,
         bool rescale, bool exact) {
        Fit_settings settings{fit, degree, degree_selection, smoothing, 0};
        return exact ? make_c1<Exact>(points, values, gradients, settings, rescale)
                     : make_c1<Fast>(points, values, gradients, settings, rescale);
      },
      py::arg("points"), py::arg("values"), py::arg("gradients"), py::arg("fit"), py::arg("degree"),
      py::arg("degree_selection"), py::arg("smoothing"), py::arg("rescale"), py::arg("exact"));
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
  m.attr("__version__") = TRIANGULAR_SPLINE_VERSION;
}
