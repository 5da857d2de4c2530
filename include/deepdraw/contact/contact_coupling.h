// Frictional contact of the sheet with rigid tools in the monolithic
// (u, lambda, z) system (doc/theory_contact.md, reference Eqs. 12 and 19).
//
// Every surface node of the sheet facing a tool forms a contact pair with
// it; each pair owns an unknown contact force lambda (3 components, the
// force of the tool on the node, N). A force-controlled tool adds one
// unknown, its position z along its axis a, with the equation
// sum_pairs a . P = F(t); a spring-backed tool (Control = spring) too, with
// sum_pairs a . P = k (z_r(t) - z), z_r its rest position (D187). The tools
// are declared in four slots,
// subsection Contact / subsection Tool 1 ... Tool 4.
#ifndef deepdraw_contact_contact_coupling_h
#define deepdraw_contact_contact_coupling_h

#include <array>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deepdraw/contact/alart_curnier_law.h>
#include <deepdraw/contact/contact_history.h>
#include <deepdraw/contact/contact_pair.h>
#include <deepdraw/contact/contact_parameters.h>
#include <deepdraw/fe/vertex_parents.h>
#include <deepdraw/geometry/rigid_tool.h>
#include <deepdraw/geometry/square_cup_tools.h>
#include <deepdraw/linear_algebra/system_matrix.h>
#include <deepdraw/process/stage.h>
#include <deepdraw/solver/multiplier_condensation.h>
#include <memory>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace contact
  {
    using namespace dealii;

    constexpr unsigned int n_tool_slots = 4;

    // A tool as subsection Contact/Tool N declares it.
    struct ToolDefinition
    {
      std::string name;
      // "square cup punch", "square cup die", "square cup blank holder",
      // "file" or "cad" (then `file`).
      std::string geometry;
      std::string file;
      // Geometry = cad: Length unit and Normals of the slot.
      std::string length_unit = "file";
      std::string normals     = "automatic";
      // Boundary id of the sheet face it touches: 4 bottom, 5 top.
      unsigned int sheet_face = 5;
      // Control = force (a stage may change it, ToolMotion).
      bool force_controlled = false;
      // Control = spring: the stiffness k (N/mm, of the model: a quarter
      // model carries a quarter of it) behind the rest position that
      // Translation gives; 0 for the other controls.
      double spring_stiffness = 0.;
      // Translation (3 expressions of t, mm, from the file position), and
      // its text for messages.
      std::shared_ptr<FunctionParser<1>> translation;
      std::string                        translation_expression;
      // "Contact/Tool N/", for messages.
      std::string parameter_prefix;
      // Force control: axis a (unit) along which the tool moves and
      // presses.
      Tensor<1, 3> axis;
    };

    // How a tool is driven in one stage of the process (process::Stage,
    // D101).
    struct ToolMotion
    {
      bool takes_part       = true;
      bool force_controlled = false;
      // > 0: backed by a spring of this stiffness (N/mm) at its rest
      // position, the translation below (D187).
      double spring_stiffness = 0.;
      // Force control and the spring make the position along the axis an
      // unknown.
      bool
      position_is_unknown() const
      {
        return takes_part && (force_controlled || spring_stiffness > 0.);
      }
      // Displacement control: the translation is origin + f(t), f the
      // declared Translation (origin 0: from the file position) or the
      // stage's (relative: origin is where the tool stood at the start of
      // the stage).
      std::shared_ptr<FunctionParser<1>> translation;
      std::string                        translation_expression;
      std::string                        translation_parameter;
      bool                               relative = false;
      Tensor<1, 3>                       origin;
      // Force control: F(t) along the axis (N), and its parameter.
      std::shared_ptr<FunctionParser<1>> force;
      std::string                        force_expression;
      std::string                        force_parameter;
    };

    class ContactCoupling
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      // Reads subsection Contact; tool files are relative to
      // prm_directory. Throws InputError naming the parameter or file.
      void
      parse_parameters(ParameterHandler &prm, const std::string &prm_directory);
      // How each tool takes part in each stage (contact_coupling_stages.cc):
      // the tools a stage names exist, a stage's translation is three
      // expressions of t, its holder force one; a tool that turns to
      // displacement control in a stage needs the stage's translation.
      // Throws InputError naming the parameter.
      void
      parse_stages(const std::vector<process::Stage> &stages);

      bool
      active() const;

      // Largest force (N) a force-controlled tool may be given (D50).
      static constexpr double max_force = 1e9;

      // Input checks that need the blank and the run (D50): Search distance
      // at most blank_diagonal; in every stage, every translation of a tool
      // that takes part finite and within +-length_bound (mm), a stage's
      // own translation 0 at its start, and every tool force finite, at
      // most max_force and positive (D176), at the stage's check loads
      // (process::Stage::check_loads). Throws InputError naming the
      // parameter, the value and the load.
      void
      check_values(const std::vector<process::Stage> &stages,
                   double                             blank_diagonal,
                   double                             length_bound) const;

      // Drives the tools as stage s (of parse_stages()) says from now on;
      // a stage's own translation starts where the tool stands. Then
      // create_pairs() builds the pairs of the tools that take part.
      void
      begin_stage(unsigned int s);
      // Whether tool k takes part in the current stage.
      bool
      takes_part(unsigned int k) const;

      // Builds the tools (square-cup builder tools need the geometry of
      // subsection Tools and the sheet thickness; a free edge of a CAD
      // tool in a symmetry plane of the model is a symmetry edge).
      void
      create_tools(const geometry::SquareCupToolParameters &square_cup,
                   double                                   sheet_thickness,
                   bool                                     symmetry_plane_x,
                   bool                                     symmetry_plane_y);

      // One pair per (vertex on the tool's sheet face, tool). vertex_dofs
      // gives the 3 displacement dofs of a vertex; unknowns of the
      // multipliers and tool positions are numbered from first_index.
      // Under mpirun vertex_owners gives the rank that evaluates the pairs
      // of each vertex (parallel::vertex_owners; empty: this one, D216).
      // Returns the number of unknowns added.
      unsigned int
      create_pairs(
        const std::vector<std::vector<unsigned int>> &face_vertices,
        const std::vector<std::array<types::global_dof_index, 3>> &vertex_dofs,
        types::global_dof_index                                    first_index,
        double                           youngs_modulus,
        double                           element_size,
        const std::vector<unsigned int> &vertex_owners = {});

      void
      add_sparsity(DynamicSparsityPattern &dsp) const;

      // The unknowns of every pair: its node's displacement dofs and its
      // multipliers, component by component, and its augmentation (for the
      // exact elimination of the multipliers, solver::MultiplierCondensation,
      // D90). A multiplier component whose displacement component is
      // prescribed (e.g. on a symmetry plane) is redundant with the
      // constraint, which carries that force, and is constrained to zero by
      // the caller.
      std::vector<solver::MultiplierBlock>
      multiplier_blocks() const;

      // Places the displacement-controlled tools at load t_new and
      // remembers where every tool was at t_old.
      void
      start_increment(double old_load, double new_load);

      // Adds the contact contributions for the current iterate:
      // `positions` are the vertex positions at t (start of increment),
      // `solution` holds du (displacement part), lambda and z; the
      // force-controlled tools are first placed at their z. Adds -r to rhs
      // (displacement rows P, multiplier rows -F_sup, tool rows
      // F(new_load) - a.P) and dr/dx to the matrix (if matrix != nullptr)
      // through the constraints. The contact forces are kept in the pairs
      // (tool_forces(), nodal_contact()), not returned in a vector.
      // Returns the number of pairs whose state (open / stick / slip, or
      // found by the search) changed since the last call.
      // With predictor = true (the tangent predictor of the increment) the
      // pairs that were open at the last converged state stay open: the
      // predictor linearises at that state (reference Eq. 13).
      unsigned int
      assemble(const std::vector<Point<3>>     &positions,
               const Vector<double>            &solution,
               const AffineConstraints<double> &constraints,
               linear_algebra::SystemMatrix    *matrix,
               Vector<double>                  &rhs,
               double                           new_load,
               bool                             predictor = false);

      // Appends the multiplier unknowns of the pairs open after the last
      // assemble(): their rows and columns hold only the diagonal 1/r (the
      // linear solver leaves them out, D60).
      void
      add_open_multipliers(
        std::vector<types::global_dof_index> &unknowns) const;

      // sqrt(sum |r F_sup|^2 + sum (holder residual)^2): a force (N).
      double
      residual_norm(const Vector<double> &rhs) const;
      // Largest |sum a.P - F(t)| / |F(t)| over the force-controlled tools
      // (0 without them); a tool with F(t) = 0 is measured against
      // zero_force_scale (N) instead.
      double
      tool_force_error(const Vector<double> &rhs,
                       double                load,
                       double                zero_force_scale) const;

      // Remembers the converged tool positions and contact states.
      void
      commit(const Vector<double> &solution);
      // What commit() remembered, for the SimulationState, and its
      // restoration on a restart (same pairs and tools, checked).
      ContactHistory
      committed_history() const;
      void
      restore(const ContactHistory &history);

      // For output, after assemble(): per vertex (index of the vertex)
      // accumulated over its pairs.
      struct NodalContact
      {
        unsigned int status       = 0; // 0 open, 1 stick, 2 slip
        double       normal_force = 0.;
        Tensor<1, 3> friction_force;
        double       gap = std::numeric_limits<double>::max();
      };
      std::vector<NodalContact>
      nodal_contact(unsigned int n_vertices) const;

      // Force of each tool on the sheet (sum of P over its pairs), and
      // translation of each tool.
      std::vector<Tensor<1, 3>>
      tool_forces() const;
      const std::vector<geometry::RigidTool> &
      tools() const;
      const std::vector<ToolDefinition> &
      tool_definitions() const;
      // Translation of displacement-controlled tool k at load t in the
      // current stage, and the force of force-controlled tool k; both throw
      // std::runtime_error naming the parameter if the value is not finite
      // (exit code 3).
      Tensor<1, 3>
      prescribed_translation(unsigned int k, double load) const;
      // The translation that subsection Contact/Tool N declares, at load t
      // (the same failure).
      Tensor<1, 3>
      declared_translation(unsigned int k, double load) const;
      double
      prescribed_force(unsigned int k, double load) const;
      // Spring-backed tool k at position z along its axis: its translation
      // (the rest translation off the axis, z along it) and the spring's
      // force k (z_r(t) - z) (D187).
      Tensor<1, 3>
      spring_tool_translation(unsigned int k,
                              double       load,
                              double       position) const;
      double
      spring_force(unsigned int k, double load, double position) const;
      // Unknowns of the positions of the force-controlled and spring-backed
      // tools.
      std::vector<types::global_dof_index>
      tool_position_unknowns() const;
      // Counts of pairs in stick and slip after the last assemble().
      unsigned int
      n_stick() const;
      unsigned int
      n_slip() const;
      // Pairs that were penetrating at the start of the run.
      unsigned int
      n_initial_penetrations(const std::vector<Point<3>> &positions) const;
      // Wall time spent in assemble() so far (s): the search, the local
      // law and the pairs' terms in the Newton system.
      double
      contact_time() const;

      // Checks that no tool passed through the sheet (D56,
      // contact_coupling_checks.cc). At the start (of the run, at load,
      // for the tools flagged in `tools`, all if empty): no node more than
      // half the sheet thickness inside a tool, and every tool's normal
      // towards the sheet face it acts on; throws InputError naming the
      // tool.
      void
      check_initial_placement(const std::vector<Point<3>> &positions,
                              double                       sheet_thickness,
                              double                       load  = 0.,
                              const std::vector<bool>     &tools = {}) const;
      // Before an increment: "" or why a displacement-controlled tool
      // moves farther than the search distance in [old_load, new_load];
      // with the converged solution, the same for force-controlled tools.
      std::string
      check_tool_motion(double old_load, double new_load) const;
      std::string
      check_tool_motion(double                old_load,
                        double                new_load,
                        const Vector<double> &solution) const;
      // After a converged increment (positions at t, du in solution): ""
      // or which node ended inside which tool.
      std::string
      check_tool_sides(const std::vector<Point<3>> &positions,
                       const Vector<double>        &solution,
                       double                       sheet_thickness) const;

      // The contact state of every pair, carried over a mesh change
      // (contact_coupling_transfer.cc, doc/theory.md §8.2): the multipliers
      // of the last two converged Newton solutions, the committed states,
      // and the tool positions z of both solutions.
      struct PairSnapshot
      {
        unsigned int                vertex;
        unsigned int                tool;
        std::array<Tensor<1, 3>, 2> multiplier;
        bool                        open_at_start;
        bool                        found;
        contact::ContactState       state;
      };
      struct Snapshot
      {
        std::vector<PairSnapshot>          pairs;
        std::vector<std::array<double, 2>> tool_position;
        // Where each tool stood (its translation).
        std::vector<Tensor<1, 3>> translation;
      };
      Snapshot
      snapshot(const Vector<double> &converged,
               const Vector<double> &previous) const;
      // After create_pairs() on the refined mesh: every pair starts from the
      // pairs of the same tool at its node's parents (an old node: itself).
      // Without parents (a new stage on the same mesh) every pair takes the
      // state and multipliers of the pair of its node and tool, if there
      // was one, exactly, and a tool that turned to force control starts
      // at its position along its axis.
      // The multipliers are nodal forces; their pressures λ/a (a: the
      // node's share of the sheet face, old_area before and new_area after
      // the refinement, by vertex) are interpolated and multiplied by the
      // new share, so that a uniform pressure is carried exactly. A pair is
      // closed only if all its parents' pairs were (slip if one slipped).
      // Writes the multipliers and tool positions into the contact blocks
      // of converged and previous (sized for the new unknowns).
      void
      transfer(const Snapshot                       &old,
               const std::vector<fe::VertexParents> &parents,
               const std::vector<double>            &old_area,
               const std::vector<double>            &new_area,
               Vector<double>                       &converged,
               Vector<double>                       &previous);

    private:
      // transfer() on the same mesh.
      void
      carry_over(const Snapshot &old,
                 Vector<double> &converged,
                 Vector<double> &previous);

      struct Pair
      {
        unsigned int                           vertex;
        unsigned int                           tool;
        std::array<types::global_dof_index, 3> u_dofs;
        types::global_dof_index                first_multiplier;
        double                                 augmentation;
        contact::ContactPairResult             result;
        bool                                   found = false;
        // Open at the last converged state (see assemble(), predictor).
        bool open_at_start = false;
      };

      // Projection of the pair's node at `solution` and its contact law
      // (pair.result); true if its state changed.
      bool
      evaluate_pair(Pair                        &pair,
                    const std::vector<Point<3>> &positions,
                    const Vector<double>        &solution,
                    bool                         predictor) const;
      // Under mpirun: every rank receives the outcome (found, state,
      // result) of the pairs the other ranks evaluated; an open pair's as
      // its normal gap only, the rest follows from its multiplier in
      // `solution` (contact_coupling_ranks.cc, D216).
      void
      exchange_pair_outcomes(const Vector<double> &solution);

      contact::ContactParameters  parameters;
      double                      search_distance = 2.;
      std::vector<ToolDefinition> definitions;
      // Per stage, per tool; and those of the current stage.
      std::vector<std::vector<ToolMotion>> stage_motions;
      std::vector<ToolMotion>              motions;
      std::vector<geometry::RigidTool>     tool_list;
      // Unknown index of the position of each force-controlled tool
      // (invalid for displacement control).
      std::vector<types::global_dof_index> position_dof;
      std::vector<double>                  position_at_start; // z_n
      // Spring-backed tools: the spring's force at the last assembly (N).
      std::vector<double>       spring_forces;
      std::vector<Tensor<1, 3>> translation_at_start;
      std::vector<Tensor<1, 3>> translation_at_end;
      std::vector<Pair>         pairs;
      // Under mpirun, the rank that evaluates each pair (empty when
      // serial).
      std::vector<unsigned int>                 pair_owners;
      std::unique_ptr<contact::AlartCurnierLaw> law;
      double                                    force_regularisation = 1.;
      double                                    total_contact_time   = 0.;
    };
  } // namespace contact
} // namespace deepdraw

#endif
