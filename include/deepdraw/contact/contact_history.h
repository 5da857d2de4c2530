// The committed contact state that the next increment starts from, as a
// restart or a mesh change carries it (state::SimulationState::contact).
#ifndef deepdraw_contact_contact_history_h
#define deepdraw_contact_contact_history_h

#include <vector>

namespace deepdraw
{
  namespace contact
  {
    // The committed contact state that the next increment starts from:
    // which pairs were open (the tangent predictor keeps them open,
    // doc/theory.md §5) and where each tool stood (z along its axis for
    // force control, 0 otherwise).
    struct ContactHistory
    {
      std::vector<unsigned char> pair_open;
      // Per pair, its state at the last evaluation (0 not found by the
      // search, else 1 + contact::ContactState): the reference from which
      // the next increment counts state changes.
      std::vector<unsigned char> pair_status;
      std::vector<double>        tool_position;
      // Per tool, 3 doubles each: where a stage's translation starts from
      // (the tool's translation at the start of the stage when the stage
      // gives the translation, else 0), and where the tool stands (its
      // translation; a tool that takes no part in a stage stays there).
      std::vector<double> tool_origin;
      std::vector<double> tool_translation;
    };
  } // namespace contact
} // namespace deepdraw

#endif
