// Copyright (c) 2026 Triangular_spline contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_PARAMETERS_H
#define CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_PARAMETERS_H

#include <CGAL/Triangular_spline/Blending/Mesh_blending_surface.h>
#include <CGAL/Triangular_spline/internal/named_parameters.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <type_traits>
#include <utility>

namespace CGAL {
namespace Triangular_spline {

/*!
  \ingroup PkgTriangularSplineBlending
  \brief the named parameters of the generalized blending (`make_blending_surface()`,
  `blending_options()`).

  Each option of `Mesh_blending_options` has a free function here (`blending_order(int)`,
  `blending_variant(Blending_variant)`, `vertex_surface_method(Vertex_surface_method)`,
  `least_squares_degree(int)`, `normals_degree(int)`, `least_interpolant_tolerance(double)`;
  see `blending_options()` for their meaning and defaults), in two forms: `f(value)`
  starts a pack, `f(value, np)` appends to the pack `np` (CGAL's or ours). CGAL's member
  functions (`.vertex_normal_map(...)`, ...) work on any pack, ours do not exist as members
  (CGAL 5.5's list is closed), hence:
  \code
  namespace TSP = CGAL::Triangular_spline::parameters;
  TSP::blending_order(1, TSP::blending_variant(Blending_variant::BASIC));
  TSP::blending_order(1, CGAL::parameters::vertex_normal_map(normals));
  TSP::blending_order(1).vertex_normal_map(normals);
  \endcode
  The namespace also makes all of `CGAL::parameters` visible, so
  `CGAL::Triangular_spline::parameters::default_values()` and
  `CGAL::Triangular_spline::parameters::vertex_normal_map()` are CGAL's.
*/
namespace parameters {

#ifndef DOXYGEN_RUNNING // documented in the namespace and in blending_options()
CGAL_TRIANGULAR_SPLINE_NAMED_PARAMETER(blending_order, int)
CGAL_TRIANGULAR_SPLINE_NAMED_PARAMETER(blending_variant, Blending_variant)
CGAL_TRIANGULAR_SPLINE_NAMED_PARAMETER(vertex_surface_method, Vertex_surface_method)
CGAL_TRIANGULAR_SPLINE_NAMED_PARAMETER(least_squares_degree, int)
CGAL_TRIANGULAR_SPLINE_NAMED_PARAMETER(normals_degree, int)
CGAL_TRIANGULAR_SPLINE_NAMED_PARAMETER(least_interpolant_tolerance, double)
#endif

} // namespace parameters

/*!
  \ingroup PkgTriangularSplineBlending
  \brief returns the `Mesh_blending_options` set by the named parameters `np`, the defaults
  of `Mesh_blending_options` for those not given. Parameters that are not options (such as
  `vertex_normal_map`) are ignored.

  The values are not checked here: `Mesh_blending_surface` rejects invalid ones.

  \tparam NamedParameters a sequence of named parameters

  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{blending_order}
      \cgalParamDescription{the blending order \f$d\f$: the surface is \f$C^d\f$}
      \cgalParamType{`int`}
      \cgalParamDefault{`2`}
      \cgalParamExtra{must be non-negative}
    \cgalParamNEnd
    \cgalParamNBegin{blending_variant}
      \cgalParamDescription{the edge-to-face reparameterization}
      \cgalParamType{`Blending_variant`}
      \cgalParamDefault{`Blending_variant::OPEN_SET`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_surface_method}
      \cgalParamDescription{how the vertex surfaces are built}
      \cgalParamType{`Vertex_surface_method`}
      \cgalParamDefault{`Vertex_surface_method::LEAST`}
    \cgalParamNEnd
    \cgalParamNBegin{least_squares_degree}
      \cgalParamDescription{the degree of the `LEAST_SQUARES` vertex surfaces}
      \cgalParamType{`int`}
      \cgalParamDefault{`2`}
      \cgalParamExtra{must be at least 1 if used}
    \cgalParamNEnd
    \cgalParamNBegin{normals_degree}
      \cgalParamDescription{the degree of the `LEAST_SQUARES_NORMALS` vertex surfaces (raised
      for high valence)}
      \cgalParamType{`int`}
      \cgalParamDefault{`4`}
      \cgalParamExtra{must be at least 2 if used}
    \cgalParamNEnd
    \cgalParamNBegin{least_interpolant_tolerance}
      \cgalParamDescription{the relative rank threshold of `least_interpolant()`}
      \cgalParamType{`double`}
      \cgalParamDefault{`1e-10`}
    \cgalParamNEnd
  \cgalNamedParamsEnd
  \returns the `Mesh_blending_options` set by the named parameters `np`, the defaults of
  `Mesh_blending_options` for those not given
*/
template <class CGAL_NP_TEMPLATE_PARAMETERS>
Mesh_blending_options blending_options(const CGAL_NP_CLASS& np = parameters::default_values()) {
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Mesh_blending_options options;
  options.order = choose_parameter(get_parameter(np, internal_np::blending_order), options.order);
  options.variant =
      choose_parameter(get_parameter(np, internal_np::blending_variant), options.variant);
  options.vertex_surface = choose_parameter(get_parameter(np, internal_np::vertex_surface_method),
                                            options.vertex_surface);
  options.least_squares_degree = choose_parameter(
      get_parameter(np, internal_np::least_squares_degree), options.least_squares_degree);
  options.normals_degree =
      choose_parameter(get_parameter(np, internal_np::normals_degree), options.normals_degree);
  options.least_tolerance = choose_parameter(
      get_parameter(np, internal_np::least_interpolant_tolerance), options.least_tolerance);
  return options;
}

/*!
  \ingroup PkgTriangularSplineBlending
  \brief builds the `Mesh_blending_surface` of `mesh` with the options and the property maps
  given as named parameters: `Mesh_blending_surface<Point_3>(mesh, blending_options(np), np)`,
  `Point_3` the value type of the vertex point map.

  \tparam PolygonMesh a model of `FaceListGraph` and `HalfedgeListGraph`
  (`CGAL::Surface_mesh`, `CGAL::Polyhedron_3`, ...)
  \tparam NamedParameters a sequence of named parameters

  \param mesh the input polygon mesh
  \param np an optional sequence of named parameters: those of `blending_options()` and the
  ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating a position to each vertex of `mesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with key type
                     `boost::graph_traits<PolygonMesh>::%vertex_descriptor` and a point of a
                     CGAL kernel `K` as value type}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, mesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_normal_map}
      \cgalParamDescription{a property map associating a normal to each vertex of `mesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with key type
                     `boost::graph_traits<PolygonMesh>::%vertex_descriptor` and value type
                     `K::Vector_3`}
      \cgalParamDefault{the property `"v:normal"` of a `Surface_mesh` if it has one,
                        otherwise normals estimated from the faces (see
                        `Mesh_blending_surface`)}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_index_map, edge_index_map, face_index_map}
      \cgalParamDescription{the numbering of the vertices, edges and faces used by the
                            surface's accessors (see `Mesh_blending_surface`)}
      \cgalParamDefault{automatically indexed internal maps}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \throws Invalid_input as the generic constructor of `Mesh_blending_surface` (invalid
  options or mesh, bad normals; a `Surface_mesh` with removed elements)
  \returns the blended surface
*/
template <class PolygonMesh, class CGAL_NP_TEMPLATE_PARAMETERS>
Mesh_blending_surface<typename boost::property_traits<
    typename GetVertexPointMap<PolygonMesh, CGAL_NP_CLASS>::const_type>::value_type>
make_blending_surface(const PolygonMesh& mesh,
                      const CGAL_NP_CLASS& np = parameters::default_values()) {
  using Point_3 = typename boost::property_traits<
      typename GetVertexPointMap<PolygonMesh, CGAL_NP_CLASS>::const_type>::value_type;
  // exact types: Vector_3 converts implicitly from segments, rays, ...
  if constexpr (!CGAL::parameters::is_default_parameter<
                    CGAL_NP_CLASS, CGAL::internal_np::vertex_normal_map_t>::value) {
    using Normal_map = std::decay_t<decltype(CGAL::parameters::get_parameter(
        np, CGAL::internal_np::vertex_normal_map))>;
    static_assert(std::is_same<typename boost::property_traits<Normal_map>::value_type,
                               typename CGAL::Kernel_traits<Point_3>::Kernel::Vector_3>::value,
                  "vertex_normal_map: the value type must be the kernel's Vector_3");
  }
  return Mesh_blending_surface<Point_3>(mesh, blending_options(np), np);
}

} // namespace Triangular_spline
} // namespace CGAL

#endif // CGAL_TRIANGULAR_SPLINE_BLENDING_BLENDING_PARAMETERS_H
