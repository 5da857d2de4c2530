// A CAD face -> rational Bézier patches and trimming polygons
// (doc/tool_files.md, "CAD tools"; decisions D45, D46).
// deal.II first: OpenCASCADE's macro Handle() breaks Trilinos' Sacado::Handle,
// which deal.II's headers declare.
#include <deal.II/base/config.h>
// OpenCASCADE:
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom2d_Line.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <GeomConvert.hxx>
#include <GeomConvert_BSplineSurfaceToBezierSurface.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_Circle.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Ellipse.hxx>
#include <Geom_Hyperbola.hxx>
#include <Geom_Line.hxx>
#include <Geom_OffsetSurface.hxx>
#include <Geom_Parabola.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_SurfaceOfLinearExtrusion.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <Standard_Failure.hxx>
#include <TColGeom_Array2OfBezierSurface.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>
#include <cmath>
#include <deepdraw/geometry/cad_face_patches.h>
#include <deepdraw/io/input_error.h>

namespace deepdraw::geometry
{
  namespace
  {
    std::string
    type_name(const Handle(Standard_Transient) & object)
    {
      return object.IsNull() ? std::string("missing")
                             : std::string(object->DynamicType()->Name());
    }

    // Curves GeomConvert::CurveToBSplineCurve converts exactly (it
    // approximates offset curves).
    bool
    is_exact_curve(Handle(Geom_Curve) curve)
    {
      while (curve->IsKind(STANDARD_TYPE(Geom_TrimmedCurve)))
        curve = Handle(Geom_TrimmedCurve)::DownCast(curve)->BasisCurve();
      return curve->IsKind(STANDARD_TYPE(Geom_Line))
             || curve->IsKind(STANDARD_TYPE(Geom_Circle))
             || curve->IsKind(STANDARD_TYPE(Geom_Ellipse))
             || curve->IsKind(STANDARD_TYPE(Geom_Parabola))
             || curve->IsKind(STANDARD_TYPE(Geom_Hyperbola))
             || curve->IsKind(STANDARD_TYPE(Geom_BezierCurve))
             || curve->IsKind(STANDARD_TYPE(Geom_BSplineCurve));
    }

    // How a parameter (u, v) of the face's surface becomes the B-spline's
    // (U, V): the same (B-spline surfaces and planes keep their
    // parametrisation), affinely (a Bézier surface cut to [u1, u2] x
    // [v1, v2] runs over [0, 1]^2), or only through the point on the
    // surface (the rational forms of circles do not run at constant
    // angular speed).
    enum class ParameterMap
    {
      identity,
      affine,
      through_point
    };
  } // namespace


  void
  reverse_patch(BezierPatch &patch, PatchTrimming &trimming)
  {
    patch = patch.reversed_u();
    trimming.u0 += trimming.du;
    trimming.du = -trimming.du;
  }


  CadFacePatches
  convert_cad_face(const TopoDS_Face                  &face,
                   const std::function<std::string()> &face_label,
                   const std::string                  &filename,
                   const double                        trimming_tolerance)
  {
    const auto fail = [&](const std::string &message)
    { throw InputError(filename + ": " + face_label() + ": " + message); };

    // The surface at its place (a copy moved by the face's location).
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
    if (surface.IsNull())
      fail("the face has no surface");

    // What GeomConvert will convert, and whether it can do so exactly.
    // Trimmed and offset surfaces are unwrapped (in any nesting): the face's
    // range bounds the surface anyway, and an offset is exact only through
    // its equivalent elementary surface.
    Handle(Geom_Surface) basis = surface;
    while (basis->IsKind(STANDARD_TYPE(Geom_RectangularTrimmedSurface))
           || basis->IsKind(STANDARD_TYPE(Geom_OffsetSurface)))
      if (basis->IsKind(STANDARD_TYPE(Geom_RectangularTrimmedSurface)))
        basis = Handle(Geom_RectangularTrimmedSurface)::DownCast(basis)
                  ->BasisSurface();
      else
      {
        const Handle(Geom_OffsetSurface) offset
          = Handle(Geom_OffsetSurface)::DownCast(basis);
        basis = offset->Surface(); // the equivalent surface, if there is one
        if (basis.IsNull())
          fail("an offset surface of a " + type_name(offset->BasisSurface())
               + " has no exact rational form (OpenCASCADE could only "
                 "approximate it)");
      }
    ParameterMap map = ParameterMap::through_point;
    if (basis->IsKind(STANDARD_TYPE(Geom_BSplineSurface))
        || basis->IsKind(STANDARD_TYPE(Geom_Plane)))
      map = ParameterMap::identity;
    else if (basis->IsKind(STANDARD_TYPE(Geom_BezierSurface)))
      map = ParameterMap::affine;
    else if (basis->IsKind(STANDARD_TYPE(Geom_SurfaceOfRevolution))
             || basis->IsKind(STANDARD_TYPE(Geom_SurfaceOfLinearExtrusion)))
    {
      const Handle(Geom_Curve) curve
        = Handle(Geom_SweptSurface)::DownCast(basis)->BasisCurve();
      if (!is_exact_curve(curve))
        fail("a " + type_name(basis) + " of a " + type_name(curve)
             + " has no exact rational form (OpenCASCADE could only "
               "approximate it)");
    }
    else if (!basis->IsKind(STANDARD_TYPE(Geom_CylindricalSurface))
             && !basis->IsKind(STANDARD_TYPE(Geom_ConicalSurface))
             && !basis->IsKind(STANDARD_TYPE(Geom_SphericalSurface))
             && !basis->IsKind(STANDARD_TYPE(Geom_ToroidalSurface)))
      fail("a surface of type " + type_name(basis)
           + " has no exact rational form");

    // Bounded by the face's parameter range. UVBounds may reach a little
    // beyond a bounded surface's own range: such bounds are snapped onto it.
    double u1, u2, v1, v2;
    BRepTools::UVBounds(face, u1, u2, v1, v2);
    if (map != ParameterMap::through_point)
    {
      double b_u1, b_u2, b_v1, b_v2;
      basis->Bounds(b_u1, b_u2, b_v1, b_v2);
      const auto snap
        = [](double &a, double &b, const double lo, const double hi)
      {
        if (std::isinf(lo) || std::isinf(hi))
          return;
        const double tolerance = 1e-9 * (hi - lo);
        if (a < lo + tolerance)
          a = lo;
        if (b > hi - tolerance)
          b = hi;
      };
      if (!basis->IsUPeriodic())
        snap(u1, u2, b_u1, b_u2);
      if (!basis->IsVPeriodic())
        snap(v1, v2, b_v1, b_v2);
    }
    if (!(u2 > u1 && v2 > v1))
      fail("the face has an empty parameter range");

    Handle(Geom_BSplineSurface) bspline;
    try
    {
      const Handle(Geom_Surface) bounded
        = new Geom_RectangularTrimmedSurface(basis, u1, u2, v1, v2);
      bspline = GeomConvert::SurfaceToBSplineSurface(bounded);
    }
    catch (const Standard_Failure &failure)
    {
      fail("OpenCASCADE cannot convert its " + type_name(basis)
           + " into a B-spline: " + failure.GetMessageString());
    }
    if (bspline.IsNull())
      fail("OpenCASCADE cannot convert its " + type_name(basis)
           + " into a B-spline");
    if (bspline->IsUPeriodic())
      bspline->SetUNotPeriodic();
    if (bspline->IsVPeriodic())
      bspline->SetVNotPeriodic();
    if (bspline->UDegree() > int(BezierPatch::max_degree)
        || bspline->VDegree() > int(BezierPatch::max_degree))
      fail("degrees " + std::to_string(bspline->UDegree()) + " x "
           + std::to_string(bspline->VDegree()) + " above the maximum "
           + std::to_string(BezierPatch::max_degree));

    // Knot spans -> Bézier patches.
    GeomConvert_BSplineSurfaceToBezierSurface converter(bspline);
    const int                                 n_u = converter.NbUPatches();
    const int                                 n_v = converter.NbVPatches();
    TColGeom_Array2OfBezierSurface            bezier(1, n_u, 1, n_v);
    converter.Patches(bezier);
    TColStd_Array1OfReal u_knots(1, n_u + 1), v_knots(1, n_v + 1);
    converter.UKnots(u_knots);
    converter.VKnots(v_knots);

    // The trimming loops in (U, V).
    const double U_first = u_knots(1), U_last = u_knots(n_u + 1);
    const double V_first = v_knots(1), V_last = v_knots(n_v + 1);
    const auto   estimate = [&](const gp_Pnt2d &uv)
    {
      return gp_Pnt2d(U_first + (uv.X() - u1) / (u2 - u1) * (U_last - U_first),
                      V_first + (uv.Y() - v1) / (v2 - v1) * (V_last - V_first));
    };
    ShapeAnalysis_Surface inverse(bspline);
    const double          inverse_precision = 1e-3 * trimming_tolerance;
    // (U, V) of the face point with surface parameters uv; `hint` is a
    // nearby (U, V) for the inversion through the point.
    const auto to_bspline = [&](const gp_Pnt2d &uv,
                                const gp_Pnt   &point,
                                const gp_Pnt2d &hint,
                                const bool      degenerate)
    {
      if (map == ParameterMap::identity)
        return uv;
      if (map == ParameterMap::affine || degenerate)
        return estimate(uv);
      return inverse.NextValueOfUV(hint, point, inverse_precision);
    };

    CadFacePatches                             result;
    std::vector<std::vector<dealii::Point<2>>> loops;
    // The face as its surface runs (the flag REVERSED only turns the
    // normal; the pcurves of seam edges are picked by edge orientation).
    const TopoDS_Face forward = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
    for (TopExp_Explorer wires(forward, TopAbs_WIRE); wires.More();
         wires.Next())
    {
      std::vector<dealii::Point<2>> loop;
      for (BRepTools_WireExplorer edges(TopoDS::Wire(wires.Current()), forward);
           edges.More();
           edges.Next())
      {
        const TopoDS_Edge &edge = edges.Current();
        double             first, last;
        const Handle(Geom2d_Curve) pcurve
          = BRep_Tool::CurveOnSurface(edge, forward, first, last);
        if (pcurve.IsNull())
          fail("an edge of the face has no curve on its surface");
        const bool degenerate = BRep_Tool::Degenerated(edge);
        if (edge.Orientation() == TopAbs_REVERSED)
          std::swap(first, last);
        Handle(Geom2d_Curve) basis_pcurve = pcurve;
        while (basis_pcurve->IsKind(STANDARD_TYPE(Geom2d_TrimmedCurve)))
          basis_pcurve
            = Handle(Geom2d_TrimmedCurve)::DownCast(basis_pcurve)->BasisCurve();
        const bool straight = basis_pcurve->IsKind(STANDARD_TYPE(Geom2d_Line))
                              && map != ParameterMap::through_point;

        // Samples (t, (U, V), point), refined until the surface image of
        // every polygon edge's midpoint is within the tolerance.
        struct Sample
        {
          double   t;
          gp_Pnt2d UV;
          gp_Pnt   point;
        };
        gp_Pnt2d   hint   = loop.empty() ? estimate(pcurve->Value(first))
                                         : gp_Pnt2d(loop.back()[0], loop.back()[1]);
        const auto sample = [&](const double t)
        {
          const gp_Pnt2d uv    = pcurve->Value(t);
          const gp_Pnt   point = surface->Value(uv.X(), uv.Y());
          const gp_Pnt2d UV    = to_bspline(uv, point, hint, degenerate);
          hint                 = UV;
          return Sample{t, UV, point};
        };
        const unsigned int  n_initial = straight ? 1 : 8;
        std::vector<Sample> samples;
        for (unsigned int k = 0; k <= n_initial; ++k)
          samples.push_back(sample(first + (last - first) * k / n_initial));
        std::vector<Sample> refined{samples.front()};
        for (unsigned int k = 1; k < samples.size(); ++k)
        {
          // Depth-first halving of [refined.back(), samples[k]].
          std::vector<std::pair<Sample, unsigned int>> pending{{samples[k], 0}};
          while (!pending.empty())
          {
            const Sample      &a     = refined.back();
            const Sample       b     = pending.back().first;
            const unsigned int depth = pending.back().second;
            hint                     = a.UV;
            const Sample m           = sample(0.5 * (a.t + b.t));
            const gp_Pnt chord_middle
              = bspline->Value(0.5 * (a.UV.X() + b.UV.X()),
                               0.5 * (a.UV.Y() + b.UV.Y()));
            if (!degenerate && depth < 30
                && chord_middle.Distance(m.point) > trimming_tolerance)
              pending.push_back({m, depth + 1});
            else
            {
              refined.push_back(b);
              pending.pop_back();
            }
          }
        }
        CadFacePatches::BoundaryEdge boundary{edge, {}, {}};
        for (const Sample &s : refined)
        {
          boundary.parameters.emplace_back(s.UV.X(), s.UV.Y());
          boundary.points.emplace_back(s.point.X(), s.point.Y(), s.point.Z());
        }
        // Consecutive edges share their end points: each loop vertex once.
        loop.insert(loop.end(),
                    boundary.parameters.begin(),
                    boundary.parameters.end() - 1);
        result.boundary.push_back(std::move(boundary));
      }
      loops.push_back(std::move(loop));
    }
    const auto domain
      = std::make_shared<const TrimmedDomain>(loops, trimming_tolerance);

    for (int j = 1; j <= n_v; ++j)
      for (int i = 1; i <= n_u; ++i)
      {
        PatchTrimming trimming;
        trimming.u0 = u_knots(i);
        trimming.du = u_knots(i + 1) - u_knots(i);
        trimming.v0 = v_knots(j);
        trimming.dv = v_knots(j + 1) - v_knots(j);
        if (domain->crosses(u_knots(i),
                            u_knots(i + 1),
                            v_knots(j),
                            v_knots(j + 1)))
        {
          trimming.domain = domain;
          result.trimmed  = true;
        }
        else if (!domain->loops().empty()
                 && !domain->contains(
                   dealii::Point<2>(trimming.u0 + 0.5 * trimming.du,
                                    trimming.v0 + 0.5 * trimming.dv)))
        {
          ++result.n_dropped;
          result.trimmed = true;
          continue;
        }

        const Handle(Geom_BezierSurface) &b = bezier(i, j);
        const unsigned int            p = b->UDegree(), q = b->VDegree();
        std::vector<dealii::Point<3>> points;
        std::vector<double>           weights;
        for (unsigned int jj = 1; jj <= q + 1; ++jj)
          for (unsigned int ii = 1; ii <= p + 1; ++ii)
          {
            const gp_Pnt &x = b->Pole(ii, jj);
            points.emplace_back(x.X(), x.Y(), x.Z());
            weights.push_back(b->Weight(ii, jj));
          }
        result.patches.emplace_back(p, q, points, weights);
        result.trimmings.push_back(trimming);
      }
    return result;
  }
} // namespace deepdraw::geometry
