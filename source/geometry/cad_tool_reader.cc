// STEP / IGES file -> RigidTool (doc/tool_files.md, "CAD tools";
// decisions D45-D49).
// deal.II first: OpenCASCADE's macro Handle() breaks Trilinos' Sacado::Handle,
// which deal.II's headers declare.
#include <deal.II/base/config.h>
// OpenCASCADE:
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Check.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <StepData_StepModel.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <csignal>
#include <deepdraw/geometry/cad_face_patches.h>
#include <deepdraw/geometry/cad_file_check.h>
#include <deepdraw/geometry/cad_occt_messages.h>
#include <deepdraw/geometry/cad_tool_reader.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/regular_file.h>
#include <filesystem>
#include <memory>
#include <sstream>
#include <unistd.h>

namespace deepdraw::geometry
{
  namespace
  {
    std::string
    lower_case(std::string text)
    {
      std::transform(text.begin(),
                     text.end(),
                     text.begin(),
                     [](const unsigned char c) { return std::tolower(c); });
      return text;
    }

    // Millimetres per unit; 0 if the name is not known.
    double
    millimetres_per(const std::string &unit_name)
    {
      const std::string name  = lower_case(unit_name);
      const bool        metre = name.find("metre") != std::string::npos
                         || name.find("meter") != std::string::npos
                         || name == "m";
      if (name == "mm" || (metre && name.find("milli") != std::string::npos))
        return 1.;
      if (name == "cm" || (metre && name.find("centi") != std::string::npos))
        return 10.;
      if (metre && name.find("micro") != std::string::npos)
        return 1e-3;
      if (metre && name.find("kilo") != std::string::npos)
        return 1e6;
      if (metre)
        return 1e3;
      if (name.find("inch") != std::string::npos || name == "in")
        return 25.4;
      if (name.find("foot") != std::string::npos
          || name.find("feet") != std::string::npos || name == "ft")
        return 304.8;
      return 0.;
    }

    // OpenCASCADE's readers can crash on a damaged file whose frame is
    // intact (cad_file_check.h); seen with single characters changed in
    // the parameter lines. While an object of this class lives, such a
    // crash ends the program with the message of an input error naming the
    // file and exit code 2 (doc/tool_files.md, D49), as before any output
    // is written, instead of a bare "Segmentation fault". The handler runs
    // on a stack of its own (sigaltstack): a crash by stack overflow leaves
    // no room on the thread's stack for it (D165).
    class CrashGuard
    {
    public:
      explicit CrashGuard(const std::string &filename)
          : message("deepdraw: error in the input: " + filename
                    + ": OpenCASCADE crashed while reading the file (it is "
                      "damaged)\n")
      {
        current            = this;
        stack_t own_stack  = {};
        own_stack.ss_sp    = signal_stack;
        own_stack.ss_size  = sizeof(signal_stack);
        own_stack.ss_flags = 0;
        sigaltstack(&own_stack, &previous_stack);
        struct sigaction action = {};
        action.sa_handler       = &CrashGuard::handle;
        action.sa_flags         = SA_ONSTACK;
        sigemptyset(&action.sa_mask);
        for (unsigned int k = 0; k < n_signals; ++k)
          sigaction(signals[k], &action, &previous[k]);
      }

      ~CrashGuard()
      {
        for (unsigned int k = 0; k < n_signals; ++k)
          sigaction(signals[k], &previous[k], nullptr);
        sigaltstack(&previous_stack, nullptr);
        current = nullptr;
      }

      CrashGuard(const CrashGuard &) = delete;
      CrashGuard &
      operator=(const CrashGuard &)
        = delete;

    private:
      static void
      handle(int)
      {
        // Only async-signal-safe calls here.
        if (current) [[maybe_unused]]
          const auto written
            = ::write(2, current->message.data(), current->message.size());
        ::_exit(2);
      }

      static constexpr unsigned int n_signals      = 3;
      static constexpr int      signals[n_signals] = {SIGSEGV, SIGBUS, SIGFPE};
      static inline CrashGuard *current            = nullptr;
      // Static: the guard is made once per CAD file, on the main thread.
      static inline char signal_stack[1 << 16];
      stack_t            previous_stack = {};
      const std::string  message;
      struct sigaction   previous[n_signals];
    };


    // The file read by OpenCASCADE, its reader kept for the entity labels
    // of faces in error messages.
    struct CadFile
    {
      std::unique_ptr<XSControl_Reader> reader;
      bool                              step = true;
      TopoDS_Shape                      shape;
      std::string                       unit_name;
      double                            unit_in_mm = 1.;

      // "face 3 (STEP entity #51)": the face's number in the shape
      // (TopExp::MapShapes order) and, if OpenCASCADE can tell, its entity
      // (a search through all transferred entities: asked for on errors
      // only).
      std::string
      face_label(const TopoDS_Shape &face, const unsigned int number) const
      {
        std::string label = "face " + std::to_string(number);
        try
        {
          // The same face (1), or the same one at another location (-1:
          // faces of a placed shape).
          const Handle(XSControl_TransferReader) &transfer
            = reader->WS()->TransferReader();
          Handle(Standard_Transient) entity
            = transfer->EntityFromShapeResult(face, 1);
          if (entity.IsNull())
            entity = transfer->EntityFromShapeResult(face, -1);
          if (entity.IsNull())
            return label;
          if (step)
          {
            const auto model
              = Handle(StepData_StepModel)::DownCast(reader->Model());
            if (!model.IsNull() && model->IdentLabel(entity) > 0)
              label += " (STEP entity #"
                       + std::to_string(model->IdentLabel(entity)) + ")";
          }
          else if (reader->Model()->Number(entity) > 0)
            label += " (IGES directory entry "
                     + std::to_string(2 * reader->Model()->Number(entity) - 1)
                     + ")";
        }
        catch (const Standard_Failure &)
        {
        }
        return label;
      }
    };

    // OpenCASCADE's first failure message without its "****" frame, as
    // " (...)", or "".
    std::string
    reason(const MutedOcctMessages &messages)
    {
      const std::string text  = messages.first_failure();
      const auto        first = text.find_first_not_of("* \n");
      if (first == std::string::npos)
        return "";
      const auto last = text.find_last_not_of("* \n");
      return " (" + text.substr(first, last - first + 1) + ")";
    }

    CadFile
    read_file(const std::string &filename, const MutedOcctMessages &messages)
    {
      io::check_regular_file(filename, "CAD file");
      if (std::filesystem::file_size(filename) == 0)
        throw InputError(filename + ": the CAD file is empty");
      const std::string extension
        = lower_case(std::filesystem::path(filename).extension());
      CadFile file;
      file.step = extension == ".step" || extension == ".stp";
      if (!file.step && extension != ".iges" && extension != ".igs")
        throw InputError(filename
                         + ": unknown CAD file extension (expected .step, "
                           ".stp, .iges or .igs)");
      const std::string format = file.step ? "STEP" : "IGES";
      const auto        fail   = [&](const std::string &message)
      { throw InputError(filename + ": " + message); };

      IFSelect_ReturnStatus status = IFSelect_RetError;
      if (file.step)
        check_step_frame(filename);
      else
        check_iges_frame(filename);
      if (file.step)
      {
        file.reader = std::make_unique<STEPControl_Reader>();
        status      = file.reader->ReadFile(filename.c_str());
      }
      else
      {
        // Keep B-spline surfaces as written (no splitting at C0 knots).
        Interface_Static::SetIVal("read.iges.bspline.continuity", 0);
        file.reader = std::make_unique<IGESControl_Reader>();
        status      = file.reader->ReadFile(filename.c_str());
      }
      if (status != IFSelect_RetDone || file.reader->Model().IsNull())
        fail("not a readable " + format + " file" + reason(messages));
      const Handle(Interface_Check) &check
        = file.reader->Model()->GlobalCheck();
      if (!check.IsNull() && check->HasFailed())
        fail("not a readable " + format + " file (" + check->CFail(1) + ")");
      if (file.reader->NbRootsForTransfer() == 0)
        fail("no shape in the " + format + " file (is it complete?)"
             + reason(messages));
      file.reader->TransferRoots();
      if (file.reader->NbShapes() == 0)
        fail("no shape could be read from the " + format
             + " file (is it complete?)" + reason(messages));
      file.shape = file.reader->OneShape();

      if (file.step)
      {
        TColStd_SequenceOfAsciiString lengths, angles, solid_angles;
        static_cast<STEPControl_Reader &>(*file.reader)
          .FileUnits(lengths, angles, solid_angles);
        if (lengths.Length() > 0)
          file.unit_name = lengths.Value(1).ToCString();
        file.unit_in_mm = millimetres_per(file.unit_name);
      }
      else
      {
        const IGESData_GlobalSection &global
          = static_cast<IGESControl_Reader &>(*file.reader)
              .IGESModel()
              ->GlobalSection();
        file.unit_name = global.UnitName().IsNull()
                           ? std::string()
                           : std::string(global.UnitName()->ToCString());
        // Unit flag of the global section (IGES 5.3, §2.2.4.3 parameter
        // 14): 1 inch, 2 mm, 4 foot, 5 mile, 6 m, 7 km, 8 mil, 9 micron,
        // 10 cm, 11 microinch; 3: named by parameter 15.
        const double per_flag[12] = {0.,
                                     25.4,
                                     1.,
                                     0.,
                                     304.8,
                                     1609344.,
                                     1e3,
                                     1e6,
                                     0.0254,
                                     1e-3,
                                     10.,
                                     2.54e-5};
        const int    flag         = global.UnitFlag();
        file.unit_in_mm           = flag >= 1 && flag <= 11 && flag != 3
                                      ? per_flag[flag]
                                      : millimetres_per(file.unit_name);
      }
      return file;
    }

    // The patch parameters of sample m of n along edge e (0: s = 0, 1:
    // s = 1, 2: t = 0, 3: t = 1), end points left out.
    std::pair<double, double>
    edge_sample(const unsigned int e,
                const unsigned int m,
                const unsigned int n)
    {
      const double r = (m + 1.) / (n + 1.);
      return e == 0   ? std::make_pair(0., r)
             : e == 1 ? std::make_pair(1., r)
             : e == 2 ? std::make_pair(r, 0.)
                      : std::make_pair(r, 1.);
    }

    // Integral of (x_s × x_t) · d over the part of the patch inside its
    // trimming (4 x 4 Gauss points), and the area of that part.
    std::pair<double, double>
    flux_and_area(const BezierPatch          &patch,
                  const PatchTrimming        &trimming,
                  const dealii::Tensor<1, 3> &d)
    {
      static const double x[4] = {0.0694318442029737,
                                  0.3300094782075719,
                                  0.6699905217924281,
                                  0.9305681557970263};
      static const double w[4] = {0.1739274225687269,
                                  0.3260725774312731,
                                  0.3260725774312731,
                                  0.1739274225687269};
      double              flux = 0., area = 0.;
      for (unsigned int i = 0; i < 4; ++i)
        for (unsigned int j = 0; j < 4; ++j)
        {
          const SurfacePoint s = patch.derivatives(x[i], x[j]);
          if (!trimming.contains(x[i], x[j], s.x_u, s.x_v))
            continue;
          const dealii::Tensor<1, 3> n = dealii::cross_product_3d(s.x_u, s.x_v);
          flux += w[i] * w[j] * (n * d);
          area += w[i] * w[j] * n.norm();
        }
      return {flux, area};
    }

    TopAbs_Orientation
    orientation_in(const TopoDS_Shape &face, const TopoDS_Shape &edge)
    {
      for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next())
        if (e.Current().IsSame(edge))
          return e.Current().Orientation();
      return TopAbs_EXTERNAL;
    }


    // A patch edge is free if one of 7 samples on it lies within `tolerance`
    // of a free face edge, on a symmetry plane if one lies on a symmetry
    // edge, shared otherwise: inside the face, along an edge another face
    // shares, or outside the trimming loops (where feet are flagged anyway).
    RigidTool::EdgeKinds
    patch_edge_kinds(const BezierPatch           &patch,
                     const PatchTrimming         &trimming,
                     const CadFacePatches        &face,
                     const std::vector<EdgeKind> &boundary_kinds,
                     const double                 tolerance)
    {
      RigidTool::EdgeKinds kinds;
      for (unsigned int e = 0; e < 4; ++e)
      {
        bool any_free = false, any_symmetry = false;
        for (unsigned int m = 0; m < 7; ++m)
        {
          const auto [s, t]            = edge_sample(e, m, 7);
          const SurfacePoint     point = patch.derivatives(s, t);
          const dealii::Point<2> uv(trimming.u0 + trimming.du * s,
                                    trimming.v0 + trimming.dv * t);
          for (unsigned int b = 0; b < face.boundary.size(); ++b)
            if (boundary_kinds[b] != EdgeKind::shared
                && polyline_distance(face.boundary[b].parameters,
                                     uv,
                                     point.x_u / trimming.du,
                                     point.x_v / trimming.dv)
                     <= tolerance)
            {
              any_free = any_free || boundary_kinds[b] == EdgeKind::free;
              any_symmetry
                = any_symmetry || boundary_kinds[b] == EdgeKind::symmetry;
            }
        }
        kinds[e] = any_free       ? EdgeKind::free
                   : any_symmetry ? EdgeKind::symmetry
                                  : EdgeKind::shared;
      }
      return kinds;
    }


    // Per face: is its normal to be turned, relative to the file (D48)?
    // automatic: first relative flips that make faces across manifold edges
    // agree (a shared edge runs in opposite directions in two faces that
    // agree), then each connected set of faces as a whole if its normals
    // point away from the sheet on average (the flux of towards_sheet
    // through it is negative); a closed shell (no free edge) keeps the
    // outward normals of its solid.
    std::vector<bool>
    normal_flips(const TopTools_IndexedMapOfShape                &faces,
                 const TopTools_IndexedDataMapOfShapeListOfShape &edge_faces,
                 const std::vector<CadFacePatches>               &converted,
                 const CadToolOptions                            &options)
    {
      const unsigned int n_faces = faces.Extent();
      if (options.normals != CadNormals::automatic)
        return std::vector<bool>(n_faces,
                                 options.normals == CadNormals::reversed);
      std::vector<int>          component(n_faces, -1);
      std::vector<bool>         relative_flip(n_faces, false);
      std::vector<double>       flux(n_faces, 0.), area(n_faces, 0.);
      std::vector<bool>         closed_component;
      std::vector<unsigned int> stack;
      for (unsigned int f = 0; f < n_faces; ++f)
      {
        const double sign
          = faces(f + 1).Orientation() == TopAbs_REVERSED ? -1. : 1.;
        for (unsigned int k = 0; k < converted[f].patches.size(); ++k)
        {
          const auto [patch_flux, patch_area]
            = flux_and_area(converted[f].patches[k],
                            converted[f].trimmings[k],
                            options.towards_sheet);
          flux[f] += sign * patch_flux;
          area[f] += patch_area;
        }
      }
      for (unsigned int start = 0; start < n_faces; ++start)
      {
        if (component[start] >= 0)
          continue;
        const int c      = closed_component.size();
        component[start] = c;
        closed_component.push_back(true);
        stack.assign(1, start);
        while (!stack.empty())
        {
          const unsigned int f = stack.back();
          stack.pop_back();
          for (TopExp_Explorer e(faces(f + 1), TopAbs_EDGE); e.More(); e.Next())
          {
            const TopoDS_Edge          &edge   = TopoDS::Edge(e.Current());
            const TopTools_ListOfShape &owners = edge_faces.FindFromKey(edge);
            if (BRep_Tool::Degenerated(edge)
                || BRep_Tool::IsClosed(edge, TopoDS::Face(faces(f + 1))))
              continue;
            if (owners.Extent() < 2)
              closed_component[c] = false;
            if (owners.Extent() != 2)
              continue;
            for (const TopoDS_Shape &owner : owners)
            {
              const unsigned int g = faces.FindIndex(owner) - 1;
              if (g == f || component[g] >= 0)
                continue;
              component[g] = c;
              // Same direction in both faces: one of them is inside out.
              relative_flip[g] = relative_flip[f]
                                 != (orientation_in(faces(f + 1), edge)
                                     == orientation_in(faces(g + 1), edge));
              stack.push_back(g);
            }
          }
        }
      }
      std::vector<double> component_flux(closed_component.size(), 0.),
        component_area(closed_component.size(), 0.);
      for (unsigned int f = 0; f < n_faces; ++f)
      {
        component_flux[component[f]] += (relative_flip[f] ? -1. : 1.) * flux[f];
        component_area[component[f]] += area[f];
      }

      std::vector<bool> flips(n_faces);
      for (unsigned int f = 0; f < n_faces; ++f)
      {
        const int c = component[f];
        flips[f]    = relative_flip[f]
                   != (!closed_component[c]
                       && component_flux[c] < -1e-9 * component_area[c]);
      }
      return flips;
    }
  } // namespace


  std::string
  CadToolReport::summary() const
  {
    std::ostringstream text;
    const auto        &corners = bounding_box.get_boundary_points();
    text << format << ", " << n_faces << " faces, " << n_patches << " patches, "
         << n_trimmed_faces << " trimmed faces (" << n_dropped_patches
         << " patches outside their loops), " << n_reversed_faces
         << " faces reversed, " << n_free_edges << " free patch edges, unit "
         << (file_unit.empty() ? std::string("(none)") : file_unit)
         << " (scale " << scale << "), box [" << corners.first[0] << ", "
         << corners.second[0] << "] x [" << corners.first[1] << ", "
         << corners.second[1] << "] x [" << corners.first[2] << ", "
         << corners.second[2] << "] mm";
    return text.str();
  }


  RigidTool
  read_cad_tool(const std::string    &filename,
                const std::string    &name,
                const CadToolOptions &options,
                CadToolReport        *report)
  {
    const MutedOcctMessages muted;
    const CrashGuard        crash_guard(filename);
    CadFile                 file;
    try
    {
      file = read_file(filename, muted);
    }
    catch (const Standard_Failure &failure)
    {
      throw InputError(filename + ": OpenCASCADE cannot read the file: "
                       + failure.GetMessageString());
    }

    // Units (D49): OpenCASCADE gives millimetres from the declared unit; an
    // explicit unit replaces the declared one.
    double scale = 1.;
    if (options.length_unit != "file")
    {
      const double wanted = millimetres_per(options.length_unit);
      if (!(wanted > 0.))
        throw InputError(filename + ": unknown length unit '"
                         + options.length_unit + "'");
      if (!(file.unit_in_mm > 0.))
        throw InputError(filename + ": the file's length unit '"
                         + file.unit_name
                         + "' is not known, so it cannot be replaced by "
                         + options.length_unit);
      scale = wanted / file.unit_in_mm;
    }
    if (scale != 1.)
    {
      gp_Trsf scaling;
      scaling.SetScale(gp_Pnt(0., 0., 0.), scale);
      file.shape = BRepBuilderAPI_Transform(file.shape, scaling, true).Shape();
    }

    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(file.shape, TopAbs_FACE, faces);
    if (faces.Extent() == 0)
      throw InputError(filename + ": the file holds no faces" + reason(muted));
    TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
    TopExp::MapShapesAndUniqueAncestors(file.shape,
                                        TopAbs_EDGE,
                                        TopAbs_FACE,
                                        edge_faces);

    // Tolerances relative to the tool's size: the trimming polygons (D46)
    // and what counts as lying in a symmetry plane.
    Bnd_Box box;
    BRepBndLib::Add(file.shape, box);
    const double size = box.IsVoid() ? 1. : std::sqrt(box.SquareExtent());
    const double trimming_tolerance = 1e-6 * size;

    // Every face as patches, oriented as its surface.
    std::vector<CadFacePatches> converted(faces.Extent());
    for (int f = 1; f <= faces.Extent(); ++f)
      try
      {
        converted[f - 1] = convert_cad_face(
          TopoDS::Face(faces(f)),
          [&]() { return file.face_label(faces(f), f); },
          filename,
          trimming_tolerance);
      }
      catch (const Standard_Failure &failure)
      {
        throw InputError(filename + ": " + file.face_label(faces(f), f)
                         + ": OpenCASCADE failed: "
                         + failure.GetMessageString());
      }

    // Which faces to turn, relative to the file (D48).
    const std::vector<bool> flips
      = normal_flips(faces, edge_faces, converted, options);

    const unsigned int n_faces = faces.Extent();
    CadToolReport      summary;
    summary.format    = file.step ? "STEP" : "IGES";
    summary.file_unit = file.unit_name;
    summary.scale     = scale;
    summary.n_faces   = n_faces;
    RigidTool tool(name);
    for (unsigned int f = 0; f < n_faces; ++f)
    {
      const bool flip_from_file = flips[f];
      const bool reverse
        = (faces(f + 1).Orientation() == TopAbs_REVERSED) != flip_from_file;
      CadFacePatches &face = converted[f];
      if (flip_from_file && !face.patches.empty())
        ++summary.n_reversed_faces;
      if (face.trimmed)
        ++summary.n_trimmed_faces;
      summary.n_dropped_patches += face.n_dropped;

      // Kinds of the face's topological edges (D47).
      std::vector<EdgeKind> boundary_kinds;
      for (const CadFacePatches::BoundaryEdge &boundary : face.boundary)
      {
        const TopoDS_Edge &edge = boundary.edge;
        EdgeKind           kind = EdgeKind::shared;
        if (!BRep_Tool::Degenerated(edge)
            && !BRep_Tool::IsClosed(edge, TopoDS::Face(faces(f + 1)))
            && edge_faces.FindFromKey(edge).Extent() < 2)
        {
          kind                   = EdgeKind::free;
          const double tolerance = 1e-9 * size;
          bool         on_x0     = options.symmetry_plane_x,
               on_y0             = options.symmetry_plane_y;
          for (const dealii::Point<3> &x : boundary.points)
          {
            on_x0 = on_x0 && std::abs(x[0]) <= tolerance;
            on_y0 = on_y0 && std::abs(x[1]) <= tolerance;
          }
          if (on_x0 || on_y0)
            kind = EdgeKind::symmetry;
        }
        boundary_kinds.push_back(kind);
      }

      for (unsigned int k = 0; k < face.patches.size(); ++k)
      {
        BezierPatch   &patch    = face.patches[k];
        PatchTrimming &trimming = face.trimmings[k];
        if (reverse)
          reverse_patch(patch, trimming);
        const RigidTool::EdgeKinds kinds
          = patch_edge_kinds(patch,
                             trimming,
                             face,
                             boundary_kinds,
                             2. * trimming_tolerance);
        for (const EdgeKind kind : kinds)
          summary.n_free_edges += kind == EdgeKind::free;
        tool.add_patch(patch, kinds, trimming);
      }
    }
    if (tool.n_patches() == 0)
      throw InputError(filename
                       + ": no face of the file has a patch inside "
                         "its trimming loops");
    summary.n_patches    = tool.n_patches();
    summary.bounding_box = tool.bounding_box();
    if (report)
      *report = summary;
    return tool;
  }
} // namespace deepdraw::geometry
