// Rigid tool -> STEP / IGES through OpenCASCADE (doc/tool_files.md, CAD
// tools; decision D47).
// deal.II first: OpenCASCADE's macro Handle() breaks Trilinos' Sacado::Handle,
// which deal.II's headers declare.
#include <deal.II/base/config.h>
// OpenCASCADE:
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRep_Builder.hxx>
#include <Geom_BezierSurface.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <IGESData_IGESWriter.hxx>
#include <IGESSelect_WorkLibrary.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <algorithm>
#include <cctype>
#include <deepdraw/geometry/cad_occt_messages.h>
#include <deepdraw/geometry/cad_tool_writer.h>
#include <deepdraw/io/input_error.h>
#include <filesystem>
#include <fstream>

namespace deepdraw::geometry
{
  namespace
  {
    std::string
    lower_case_extension(const std::string &filename)
    {
      std::string extension = std::filesystem::path(filename).extension();
      std::transform(extension.begin(),
                     extension.end(),
                     extension.begin(),
                     [](const unsigned char c) { return std::tolower(c); });
      return extension;
    }

    // The patch as an OCCT Bézier surface: poles (i + 1, j + 1) = P_ij.
    TopoDS_Face
    make_face(const BezierPatch &patch)
    {
      const unsigned int   p = patch.degree_u(), q = patch.degree_v();
      TColgp_Array2OfPnt   poles(1, p + 1, 1, q + 1);
      TColStd_Array2OfReal weights(1, p + 1, 1, q + 1);
      for (unsigned int j = 0; j <= q; ++j)
        for (unsigned int i = 0; i <= p; ++i)
        {
          const dealii::Point<3> &x = patch.control_point(i, j);
          poles(i + 1, j + 1)       = gp_Pnt(x[0], x[1], x[2]);
          weights(i + 1, j + 1)     = patch.weight(i, j);
        }
      const Handle(Geom_BezierSurface) surface
        = new Geom_BezierSurface(poles, weights);
      BRepBuilderAPI_MakeFace maker(surface, Precision::Confusion());
      if (!maker.IsDone())
        throw InputError("cannot make a face of a tool patch");
      return maker.Face();
    }

    // The faces of all patches, sewn where they meet. The sewing tolerance
    // (1e-9 of the tool size) is far above the round-off of patch corners
    // that coincide (a few 1e-16 relative) and far below any real gap.
    TopoDS_Shape
    make_shape(const RigidTool &tool)
    {
      double size = 1.;
      for (const BezierPatch &patch : tool.patches())
        size = std::max(size, patch.length_scale());
      BRepBuilderAPI_Sewing sewing(1e-9 * size);
      for (const BezierPatch &patch : tool.patches())
        sewing.Add(make_face(patch));
      sewing.Perform();
      return sewing.SewedShape();
    }
  } // namespace


  void
  write_cad_tool(const RigidTool   &tool,
                 const std::string &filename,
                 const std::string &unit)
  {
    const std::string extension = lower_case_extension(filename);
    const bool        step      = extension == ".step" || extension == ".stp";
    const bool        iges      = extension == ".iges" || extension == ".igs";
    if (!step && !iges)
      throw InputError(filename
                       + ": unknown CAD file extension (expected .step, "
                         ".stp, .iges or .igs)");
    if (tool.n_patches() == 0)
      throw InputError(filename + ": the tool '" + tool.name()
                       + "' has no patches");

    const MutedOcctMessages muted;
    bool                    written = false;
    try
    {
      const TopoDS_Shape shape = make_shape(tool);
      if (step)
      {
        // The unit before the writer: its model takes it when made.
        STEPControl_Controller::Init();
        Interface_Static::SetCVal("write.step.unit", unit.c_str());
        STEPControl_Writer writer;
        written = writer.Transfer(shape, STEPControl_AsIs) == IFSelect_RetDone
                  && writer.Write(filename.c_str()) == IFSelect_RetDone;
      }
      else
      {
        IGESControl_Controller::Init();
        IGESControl_Writer writer(unit.c_str(), /*B-rep mode=*/1);
        if (writer.AddShape(shape))
        {
          // IGESControl_Writer::Write prints 9 decimals (weights to 3e-10,
          // positions to 5e-10 mm). Here: 17 decimals in [0.1, 1000) (the
          // doubles come back), 16 significant digits elsewhere, no zero
          // suppression (OpenCASCADE's cuts numbers longer than 16
          // characters, exponent included); at most 23 characters, the
          // size of IGESData_IGESWriter's buffer. Otherwise the same steps
          // as IGESControl_Writer::Write.
          writer.ComputeModel();
          IGESData_IGESWriter iges_writer(writer.Model());
          iges_writer.FloatWriter().SetFormat("%.15E");
          iges_writer.FloatWriter().SetFormatForRange("%.17f", 0.1, 1000.);
          iges_writer.FloatWriter().SetZeroSuppress(false);
          iges_writer.SendModel(IGESSelect_WorkLibrary::DefineProtocol());
          std::ofstream out(filename);
          written = out && iges_writer.Print(out);
          out.close();
          written = written && out.good();
        }
      }
    }
    catch (const Standard_Failure &failure)
    {
      throw InputError(filename + ": OpenCASCADE failed to write the tool '"
                       + tool.name() + "': " + failure.GetMessageString());
    }
    if (!written)
      throw InputError(filename + ": cannot write the CAD file");
  }


  std::vector<std::string>
  write_cad_tool_files(const std::vector<RigidTool> &tools,
                       const std::string            &directory)
  {
    std::filesystem::create_directories(directory);
    std::vector<std::string> filenames;
    for (const RigidTool &tool : tools)
    {
      std::string stem = tool.name();
      std::replace(stem.begin(), stem.end(), ' ', '_');
      for (const char *extension : {".step", ".iges"})
      {
        const std::string filename
          = (std::filesystem::path(directory) / (stem + extension)).string();
        write_cad_tool(tool, filename);
        filenames.push_back(filename);
      }
    }
    return filenames;
  }
} // namespace deepdraw::geometry
