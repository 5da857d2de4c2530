#include <algorithm>
#include <cmath>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/io/binary_stream.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/state/simulation_state.h>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace state
  {
    namespace
    {
      // A plain binary image in this machine's byte order, with a tag and
      // counts, so that a truncated or foreign stream is detected.
      constexpr char tag[] = "deepdraw-state-5";
      // Format 5 with more than nine enhanced parameters per cell (3 or 4
      // points through the thickness, D202): their number comes before the
      // cells' block. Format 5 itself stays what it was (nine).
      constexpr char tag_with_thickness_modes[] = "deepdraw-state-6";
      // Written before releases (D150): no end force scale, release loads
      // or supports.
      constexpr char tag_before_release[] = "deepdraw-state-4";
      // Written before stages existed: no stage, no tool origins (D101).
      constexpr char tag_without_stages[] = "deepdraw-state-3";
      static_assert(sizeof(tag) == sizeof(tag_without_stages));
      static_assert(sizeof(tag) == sizeof(tag_before_release));
      static_assert(sizeof(tag) == sizeof(tag_with_thickness_modes));

      constexpr char source[] = "simulation state: the stream";

      template <typename T>
      void
      put(std::ostream &stream, const T &value)
      {
        io::write_value(stream, value);
      }

      template <typename T>
      void
      get(std::istream &stream, T &value)
      {
        io::read_value(stream, value, source);
      }

      void
      put_doubles(std::ostream &stream, const double *values, std::size_t n)
      {
        put(stream, n);
        stream.write(reinterpret_cast<const char *>(values),
                     n * sizeof(double));
      }

      // A count of elements of element_size bytes, at most what the stream
      // holds.
      std::size_t
      get_count(std::istream      &stream,
                const std::size_t  element_size,
                const std::string &what)
      {
        return io::read_count(stream, element_size, source, what);
      }

      void
      get_values(std::istream &stream, double *values, const std::size_t n)
      {
        io::read_bytes(stream, values, n * sizeof(double), source);
      }

      // Every value of a block must be finite (a damaged checkpoint of a
      // format without a checksum).
      // first: the place of values[0] in the block, for the message.
      void
      check_finite(const double      *values,
                   const std::size_t  n,
                   const std::string &what,
                   const std::size_t  first = 0)
      {
        for (std::size_t i = 0; i < n; ++i)
          if (!std::isfinite(values[i]))
            throw std::runtime_error(
              what + ": value " + std::to_string(first + i) + " is "
              + io::to_string(values[i]) + ", not a finite number");
      }

      // The doubles of one quadrature point: stress, back stress (6 + 6
      // independent components), epbar, the 9 entries of R.
      constexpr std::size_t doubles_per_point = 22;

      void
      pack(const fe::QuadraturePointHistory &point, double *values)
      {
        unsigned int k = 0;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
          {
            values[k++] = point.state.stress[i][j];
            values[k++] = point.state.back_stress[i][j];
          }
        values[k++] = point.state.equivalent_plastic_strain;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            values[k++] = point.material_axes[i][j];
      }

      void
      unpack(const double *values, fe::QuadraturePointHistory &point)
      {
        unsigned int k = 0;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
          {
            point.state.stress[i][j]      = values[k++];
            point.state.back_stress[i][j] = values[k++];
          }
        point.state.equivalent_plastic_strain = values[k++];
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            point.material_axes[i][j] = values[k++];
      }

      // The history's points are packed and unpacked a block at a time, so
      // that no copy of the whole history is made (D221).
      constexpr std::size_t points_per_block = 4096;

      void
      put_history(std::ostream                                  &stream,
                  const std::vector<fe::QuadraturePointHistory> &history)
      {
        put(stream, doubles_per_point * history.size());
        std::vector<double> block;
        for (std::size_t first = 0; first < history.size();
             first += points_per_block)
        {
          const std::size_t n
            = std::min(points_per_block, history.size() - first);
          block.resize(doubles_per_point * n);
          for (std::size_t q = 0; q < n; ++q)
            pack(history[first + q], &block[doubles_per_point * q]);
          stream.write(reinterpret_cast<const char *>(block.data()),
                       block.size() * sizeof(double));
        }
      }

      // n_points points whose count of doubles has been read; the count
      // was checked against the bytes left (get_count).
      void
      get_history(std::istream                            &stream,
                  const std::size_t                        n_points,
                  std::vector<fe::QuadraturePointHistory> &history)
      {
        history.resize(n_points);
        std::vector<double> block;
        for (std::size_t first = 0; first < n_points; first += points_per_block)
        {
          const std::size_t n = std::min(points_per_block, n_points - first);
          block.resize(doubles_per_point * n);
          get_values(stream, block.data(), block.size());
          check_finite(block.data(),
                       block.size(),
                       "history",
                       doubles_per_point * first);
          for (std::size_t q = 0; q < n; ++q)
            unpack(&block[doubles_per_point * q], history[first + q]);
        }
      }

      // A cell's enhanced parameters as stored, for n of them: values,
      // evaluated_at, correction, the sensitivity's first n rows (with
      // n = 9 the bytes of the nine-parameter struct of format 5).
      std::size_t
      doubles_per_cell(const unsigned int n)
      {
        return n + fe::dofs_per_cell + n + n * fe::dofs_per_cell;
      }

      void
      pack(const fe::EnhancedParameters &cell,
           const unsigned int            n,
           double                       *out)
      {
        out = std::copy_n(cell.values.begin(), n, out);
        out
          = std::copy(cell.evaluated_at.begin(), cell.evaluated_at.end(), out);
        out = std::copy_n(cell.correction.begin(), n, out);
        std::copy_n(cell.sensitivity.begin(), n * fe::dofs_per_cell, out);
      }

      void
      unpack(const double           *in,
             const unsigned int      n,
             fe::EnhancedParameters &cell)
      {
        cell = fe::EnhancedParameters();
        std::copy_n(in, n, cell.values.begin());
        in += n;
        std::copy_n(in, fe::dofs_per_cell, cell.evaluated_at.begin());
        in += fe::dofs_per_cell;
        std::copy_n(in, n, cell.correction.begin());
        in += n;
        std::copy_n(in, n * fe::dofs_per_cell, cell.sensitivity.begin());
      }

      void
      put_vector(std::ostream &stream, const Vector<double> &vector)
      {
        put_doubles(stream, vector.begin(), vector.size());
      }

      void
      get_vector(std::istream      &stream,
                 Vector<double>    &vector,
                 const std::string &what)
      {
        vector.reinit(get_count(stream, sizeof(double), what));
        get_values(stream, vector.begin(), vector.size());
        check_finite(vector.begin(), vector.size(), what);
      }

      void
      get_doubles(std::istream        &stream,
                  std::vector<double> &values,
                  const std::string   &what)
      {
        values.resize(get_count(stream, sizeof(double), what));
        get_values(stream, values.data(), values.size());
        check_finite(values.data(), values.size(), what);
      }

      // The load, its last step and the increment count.
      void
      read_increment(std::istream &stream, SimulationState &state)
      {
        get(stream, state.load);
        get(stream, state.last_load_increment);
        get(stream, state.increment_number);
        if (!std::isfinite(state.load))
          throw std::runtime_error("load = " + io::to_string(state.load)
                                   + " (must be finite)");
        if (!std::isfinite(state.last_load_increment)
            || state.last_load_increment < 0.)
          throw std::runtime_error("last load increment = "
                                   + io::to_string(state.last_load_increment)
                                   + " (must be finite and not negative)");
      }

      // Which pairs were open (0 or 1), each pair's state (0 ... 3: not
      // found, 1 + open, stick, slip) and the tool positions.
      void
      read_contact(std::istream &stream, contact::ContactHistory &contact)
      {
        const std::pair<std::vector<unsigned char> *, unsigned char> blocks[]
          = {{&contact.pair_open, 1}, {&contact.pair_status, 3}};
        for (const auto &[bytes, largest] : blocks)
        {
          bytes->resize(get_count(stream, 1, "contact pairs"));
          io::read_bytes(stream, bytes->data(), bytes->size(), source);
          for (const unsigned char value : *bytes)
            if (value > largest)
              throw std::runtime_error(
                "contact pairs: a pair's state is " + std::to_string(value)
                + ", allowed are 0 to " + std::to_string(largest));
        }
        get_doubles(stream, contact.tool_position, "tool positions");
      }

      // Per cycle the refined cells as (level, index, refinement case).
      void
      read_refinements(std::istream                                 &stream,
                       std::vector<std::vector<std::array<int, 3>>> &cycles)
      {
        cycles.resize(get_count(stream, sizeof(std::size_t), "refinements"));
        for (auto &cycle : cycles)
        {
          cycle.resize(
            get_count(stream, sizeof(cycle[0]), "refinements of a cycle"));
          io::read_bytes(stream,
                         cycle.data(),
                         cycle.size() * sizeof(cycle[0]),
                         source);
          for (const auto &[level, index, refinement] : cycle)
            if (level < 0 || index < 0 || refinement < 1 || refinement > 7)
              throw std::runtime_error(
                "refinements: cell (" + std::to_string(level) + ", "
                + std::to_string(index) + ") with refinement case "
                + std::to_string(refinement)
                + " (a level and index of 0 or more and a case of 1 to 7)");
        }
      }

      // The stage, whether it has ended, its force scale, the tools'
      // origins and translations.
      void
      read_stage(std::istream &stream, SimulationState &state)
      {
        get(stream, state.stage);
        unsigned char completed = 0;
        get(stream, completed);
        if (completed > 1)
          throw std::runtime_error("stage completed = "
                                   + std::to_string(completed)
                                   + " (must be 0 or 1)");
        state.stage_completed = completed != 0;
        get(stream, state.stage_force_scale);
        if (!std::isfinite(state.stage_force_scale)
            || state.stage_force_scale < 0.)
          throw std::runtime_error("stage force scale = "
                                   + io::to_string(state.stage_force_scale)
                                   + " (must be finite and not negative)");
        get_doubles(stream, state.contact.tool_origin, "tool origins");
        get_doubles(stream,
                    state.contact.tool_translation,
                    "tool translations");
      }
    } // namespace


    void
    SimulationState::write(std::ostream &stream) const
    {
      // The enhanced parameters per cell follow from the points per cell
      // (D202).
      const unsigned int n_enhanced
        = enhanced_parameters.empty()
            ? 9
            : fe::n_enhanced_parameters(
              fe::ElementTechnology::incompatible_modes,
              fe::points_through_thickness(history.size()
                                           / enhanced_parameters.size()));
      const bool thickness_modes = n_enhanced > 9;
      stream.write(thickness_modes ? tag_with_thickness_modes : tag,
                   sizeof(tag));
      put(stream, load);
      put(stream, last_load_increment);
      put(stream, increment_number);
      static_assert(sizeof(Point<3>) == 3 * sizeof(double),
                    "a Point<3> is three doubles");
      put_doubles(stream,
                  reinterpret_cast<const double *>(vertices.data()),
                  3 * vertices.size());
      put_vector(stream, total_displacement);
      put_vector(stream, converged_solution);
      put_vector(stream, previous_converged_solution);
      put_history(stream, history);
      if (thickness_modes)
        put(stream, n_enhanced);
      put(stream, enhanced_parameters.size());
      std::vector<double> cell_doubles(doubles_per_cell(n_enhanced));
      for (const fe::EnhancedParameters &cell : enhanced_parameters)
      {
        pack(cell, n_enhanced, cell_doubles.data());
        stream.write(reinterpret_cast<const char *>(cell_doubles.data()),
                     cell_doubles.size() * sizeof(double));
      }
      put(stream, next_increment);
      for (const auto *bytes : {&contact.pair_open, &contact.pair_status})
      {
        put(stream, bytes->size());
        stream.write(reinterpret_cast<const char *>(bytes->data()),
                     bytes->size());
      }
      put_doubles(stream,
                  contact.tool_position.data(),
                  contact.tool_position.size());
      put(stream, refinements.size());
      for (const auto &cycle : refinements)
      {
        put(stream, cycle.size());
        stream.write(reinterpret_cast<const char *>(cycle.data()),
                     cycle.size() * sizeof(cycle[0]));
      }
      put(stream, stage);
      put(stream, static_cast<unsigned char>(stage_completed ? 1 : 0));
      put(stream, stage_force_scale);
      for (const auto *values :
           {&contact.tool_origin, &contact.tool_translation})
        put_doubles(stream, values->data(), values->size());
      put(stream, end_force_scale);
      put_vector(stream, release_loads);
      put(stream, release_support_vertices.size());
      stream.write(reinterpret_cast<const char *>(
                     release_support_vertices.data()),
                   release_support_vertices.size() * sizeof(unsigned int));
      put_vector(stream, release_start_displacement);
      if (!stream)
        throw std::runtime_error("simulation state: writing failed");
    }


    void
    SimulationState::read(std::istream &stream)
    {
      // The tag's bytes as read, its final NUL included: a damaged tag
      // need not end in one (found by fuzz/checkpoint_fuzzer.cc).
      std::string read_tag(sizeof(tag), '\0');
      stream.read(read_tag.data(), sizeof(tag));
      const auto is = [&](const char(&expected)[sizeof(tag)])
      { return stream && read_tag == std::string(expected, sizeof(tag)); };
      const bool thickness_modes = is(tag_with_thickness_modes);
      const bool with_release    = thickness_modes || is(tag);
      const bool with_stages     = with_release || is(tag_before_release);
      if (!with_stages && !is(tag_without_stages))
        throw std::runtime_error("simulation state: not a deepdraw state");
      read_increment(stream, *this);
      std::size_t n = get_count(stream, sizeof(double), "vertices");
      if (n % 3 != 0)
        throw std::runtime_error("simulation state: bad vertex block");
      vertices.resize(n / 3);
      get_values(stream, reinterpret_cast<double *>(vertices.data()), n);
      check_finite(reinterpret_cast<const double *>(vertices.data()),
                   n,
                   "vertices");
      get_vector(stream, total_displacement, "total displacement");
      get_vector(stream, converged_solution, "converged solution");
      get_vector(stream,
                 previous_converged_solution,
                 "previous converged solution");
      n = get_count(stream, sizeof(double), "history");
      if (n % doubles_per_point != 0)
        throw std::runtime_error("simulation state: bad history block");
      get_history(stream, n / doubles_per_point, history);
      unsigned int n_enhanced = 9;
      if (thickness_modes)
      {
        get(stream, n_enhanced);
        if (n_enhanced % 3 != 0 || n_enhanced < 9
            || n_enhanced > fe::max_enhanced)
          throw std::runtime_error("enhanced parameters per cell = "
                                   + std::to_string(n_enhanced)
                                   + " (9, 12 or 15)");
      }
      std::vector<double> cell_doubles(doubles_per_cell(n_enhanced));
      enhanced_parameters.resize(get_count(stream,
                                           cell_doubles.size() * sizeof(double),
                                           "enhanced parameters"));
      for (fe::EnhancedParameters &cell : enhanced_parameters)
      {
        get_values(stream, cell_doubles.data(), cell_doubles.size());
        check_finite(cell_doubles.data(),
                     cell_doubles.size(),
                     "enhanced parameters");
        unpack(cell_doubles.data(), n_enhanced, cell);
      }
      get(stream, next_increment);
      if (!std::isfinite(next_increment) || !(next_increment > 0.))
        throw std::runtime_error(
          "next increment = " + io::to_string(next_increment)
          + " (the load stepping's next step must be positive and finite)");
      read_contact(stream, contact);
      read_refinements(stream, refinements);
      stage             = 0;
      stage_completed   = false;
      stage_force_scale = 0.;
      end_force_scale   = -1.;
      release_loads.reinit(0);
      release_support_vertices.clear();
      release_start_displacement.reinit(0);
      contact.tool_origin.assign(3 * contact.tool_position.size(), 0.);
      contact.tool_translation.clear();
      if (!with_stages)
        return;
      read_stage(stream, *this);
      if (!with_release)
        return;
      get(stream, end_force_scale);
      if (!std::isfinite(end_force_scale) || end_force_scale < -1.)
        throw std::runtime_error("end force scale = "
                                 + io::to_string(end_force_scale)
                                 + " (must be finite, -1 or more)");
      get_vector(stream, release_loads, "release loads");
      const std::size_t n_supports
        = get_count(stream, sizeof(unsigned int), "release supports");
      release_support_vertices.resize(n_supports);
      io::read_bytes(stream,
                     release_support_vertices.data(),
                     n_supports * sizeof(unsigned int),
                     source);
      for (const unsigned int vertex : release_support_vertices)
        if (vertex >= vertices.size())
          throw std::runtime_error("release supports: vertex "
                                   + std::to_string(vertex) + " of a sheet of "
                                   + std::to_string(vertices.size())
                                   + " vertices");
      get_vector(stream,
                 release_start_displacement,
                 "release start displacement");
    }
  } // namespace state
} // namespace deepdraw
