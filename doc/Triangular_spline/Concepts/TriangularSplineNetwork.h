/*!
\ingroup PkgTriangularSplineConcepts
\cgalConcept

A spline network: a triangulated planar domain with one Bézier patch per face. It is what
`certify_continuity()`, `evaluate_functional()`, `evaluate_at()`, `evaluate_jets()`,
`evaluate_jet()`, `tessellate()` and `write_spline_file()` take, so that any construction
of the package can be certified, evaluated, tessellated and saved the same way.

The patch of a face is over the three corners of that face, in any order (a spline file
keeps its own vertex order); adjacent patches meet along the shared edge of the domain.
Patches of one network usually share one degree; `degree()` is the largest.

\cgalHasModel `CGAL::Triangular_spline::C1_quintic_spline` (Xu's construction)
\cgalHasModel `CGAL::Triangular_spline::Patch_network` (patches stored as given)
\cgalHasModel `CGAL::Triangular_spline::Spline_file` (a spline read from a file)
\cgalHasModel `CGAL::Triangular_spline::Mann_interpolant` (Mann's interpolant)
*/
class TriangularSplineNetwork {
public:
  /// a model of `Kernel`, the kernel of the domain points and of the number type `FT`
  typedef unspecified_type Geom_traits;
  /// `Planar_domain<Geom_traits>::Index`
  typedef unspecified_type Index;

  /// returns the triangulated domain.
  /// \returns the triangulated domain
  const CGAL::Triangular_spline::Planar_domain<Geom_traits>& domain() const;

  /// returns the patch of face `f`: a `Bezier_triangle<Geom_traits, Value>` (by value or by
  /// const reference), `Value` being `Geom_traits::FT` (functional) or a vector type
  /// (parametric); the same `Value` for every face.
  /// \param f the index of a face
  /// \returns the patch of face `f`
  CGAL::Triangular_spline::Bezier_triangle<Geom_traits, Value> patch(Index f) const;

  /// returns the largest degree of the patches.
  /// \returns the largest degree of the patches
  int degree() const;
};
