// SheetModel: the release stages of springback (doc/user_guide.md §2.6,
// D150, D151): the forces released as loads that fall to zero over the
// stage, the supports that stop the sheet's rigid-body modes, and the
// checks that they do, when the input is read and where the sheet stands
// when the stage begins.
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/problem/sheet_model.h>
#include <deepdraw/process/rigid_body_modes.h>

namespace deepdraw
{
  namespace problem
  {
    namespace
    {
      // The components a release stage holds: its prescribed faces (the
      // symmetry planes among them) at the vertices' positions `at`, and
      // the supports at `support_points`.
      process::RigidBodyModes
      held_components(const process::Stage                         &stage,
                      const std::vector<std::vector<unsigned int>> &faces,
                      const std::vector<Point<3>>                  &at,
                      const std::vector<Point<3>> &support_points)
      {
        process::RigidBodyModes modes;
        for (const process::PrescribedDisplacement &entry :
             stage.prescribed.entries)
          for (const unsigned int vertex : faces[entry.boundary_id])
            modes.hold(at[vertex], entry.component);
        for (unsigned int s = 0; s < stage.supports.size(); ++s)
          for (unsigned int c = 0; c < 3; ++c)
            if (stage.supports[s].components[c])
              modes.hold(support_points[s], c);
        return modes;
      }

      // "" if no mode is free, else what the message says of them.
      std::string
      describe_free_modes(const process::RigidBodyModes &modes)
      {
        const std::vector<std::string> free = modes.free_modes();
        if (free.empty())
          return "";
        std::string names;
        for (const std::string &name : free)
          names += (names.empty() ? "" : ", ") + name;
        return "the released sheet is free to move (" + names
               + "): the symmetry planes, the stage's Prescribed "
                 "displacements and its supports stop "
               + std::to_string(6 - free.size())
               + " of the 6 rigid-body modes; allowed are supports that "
                 "stop all six, e.g. 'point(X, Y, Z): ux uy uz; point(...): "
                 "uy uz; point(...): uz' at three points not on one line";
      }
    } // namespace


    void
    SheetModel::check_release_supports() const
    {
      for (const process::Stage &stage : parameters.stages)
      {
        if (stage.kind != process::Stage::Kind::release)
          continue;
        std::vector<Point<3>> points;
        for (const process::ReleaseSupport &support : stage.supports)
          points.push_back(support.point);
        const std::string why = describe_free_modes(
          held_components(stage,
                          discretisation.face_vertices(),
                          discretisation.initial_vertices(),
                          points));
        if (!why.empty())
          throw InputError(
            stage.parameter_prefix + "Release supports = '"
            + io::one_line(stage.supports.empty() ? std::string()
                                                  : stage.supports[0].item)
            + (stage.supports.size() > 1 ? "; ...'" : "'") + ": " + why);
      }
    }


    void
    SheetModel::find_release_supports()
    {
      committed.release_support_vertices.clear();
      committed.release_start_displacement.reinit(0);
      if (stage().kind != process::Stage::Kind::release)
      {
        committed.release_loads.reinit(0);
        return;
      }
      committed.release_start_displacement = committed.total_displacement;
      // The nearest node where the sheet stands; not a hanging one (its
      // dofs follow their masters).
      const std::vector<Point<3>> &x
        = discretisation.triangulation().get_vertices();
      const std::vector<bool> &used
        = discretisation.triangulation().get_used_vertices();
      const AffineConstraints<double> &hanging
        = discretisation.hanging_node_constraints();
      std::vector<Point<3>> points;
      for (const process::ReleaseSupport &support : stage().supports)
      {
        unsigned int nearest  = numbers::invalid_unsigned_int;
        double       distance = std::numeric_limits<double>::max();
        for (unsigned int v = 0; v < x.size(); ++v)
          if (used[v]
              && !hanging.is_constrained(discretisation.vertex_dofs()[v][0])
              && x[v].distance(support.point) < distance)
          {
            nearest  = v;
            distance = x[v].distance(support.point);
          }
        committed.release_support_vertices.push_back(nearest);
        points.push_back(x[nearest]);
      }
      // Two points may have found the same node, or nodes on one line.
      const std::string why = describe_free_modes(
        held_components(stage(), discretisation.face_vertices(), x, points));
      if (!why.empty())
        throw InputError(stage().parameter_prefix
                         + "Release supports: at the nodes found " + why);
    }


    std::vector<types::global_dof_index>
    SheetModel::held_dofs() const
    {
      std::vector<types::global_dof_index> dofs;
      if (stage().kind != process::Stage::Kind::release)
        return dofs;
      const std::vector<unsigned int> &vertices
        = committed.release_support_vertices;
      for (unsigned int s = 0; s < vertices.size(); ++s)
        for (unsigned int c = 0; c < 3; ++c)
          if (stage().supports[s].components[c])
            dofs.push_back(discretisation.vertex_dofs()[vertices[s]][c]);
      return dofs;
    }


    double
    SheetModel::release_factor(const double load) const
    {
      const process::Stage &current = stage();
      if (!current.releases_forces())
        return 0.;
      const double fraction
        = (current.end_load - load) / (current.end_load - current.start_load);
      return std::min(1., std::max(0., fraction));
    }


    void
    SheetModel::add_release_loads(const AffineConstraints<double> &constraints,
                                  const double                     load,
                                  Vector<double>                  &rhs) const
    {
      // rhs = -r = f_ext - f_int: the loads as the contact forces they
      // replace. They were condensed onto the masters of hanging vertices
      // with the internal forces they come from.
      const double factor = release_factor(load);
      if (factor == 0. || committed.release_loads.size() == 0)
        return;
      for (types::global_dof_index i = 0; i < committed.release_loads.size();
           ++i)
        if (!constraints.is_constrained(i))
          rhs[i] += factor * committed.release_loads[i];
    }


    std::string
    SheetModel::end_stage()
    {
      const process::Stage &current = stage();
      if (current.kind == process::Stage::Kind::release
          && current.release_method
               == process::Stage::ReleaseMethod::tool_retraction)
      {
        const unsigned int closed
          = contact_coupling.n_stick() + contact_coupling.n_slip();
        if (closed > 0)
          return "the tool retraction of stage "
                 + std::to_string(committed.stage + 1) + " '" + current.name
                 + "' ended with " + std::to_string(closed)
                 + " contact pair(s) still closed; the tools must move until "
                   "the sheet is free of them ("
                 + current.parameter_prefix + "Tool N/Translation)";
      }
      // Nothing is assembled between here and the next stage's start: the
      // last assembly is the converged state's (FormingProblem writes no
      // periodic checkpoint at a stage's end, this one follows).
      committed.end_force_scale = force_scale();
      const unsigned int next   = committed.stage + 1;
      if (next < parameters.stages.size()
          && parameters.stages[next].releases_forces())
      {
        // Everything that held the sheet: the internal forces at the
        // converged state balance the contact forces and the reactions of
        // the prescribed dofs (doc/theory.md §9.1).
        committed.release_loads.reinit(discretisation.n_displacement_dofs());
        for (types::global_dof_index i = 0; i < committed.release_loads.size();
             ++i)
          committed.release_loads[i] = internal_forces[i];
      }
      committed.stage_completed = true;
      return "";
    }
  } // namespace problem
} // namespace deepdraw
