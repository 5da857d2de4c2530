#include <deepdraw/io/binary_stream.h>
#include <deepdraw/state/simulation_state.h>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>

namespace deepdraw
{
  namespace state
  {
    namespace
    {
      // A plain binary image in this machine's byte order, with a tag and
      // counts, so that a truncated or foreign stream is detected.
      constexpr char tag[] = "deepdraw-state-5";
      // Written before releases (D150): no end force scale, release loads
      // or supports.
      constexpr char tag_before_release[] = "deepdraw-state-4";
      // Written before stages existed: no stage, no tool origins (D101).
      constexpr char tag_without_stages[] = "deepdraw-state-3";
      static_assert(sizeof(tag) == sizeof(tag_without_stages));
      static_assert(sizeof(tag) == sizeof(tag_before_release));

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

      // A block written by put_doubles: its count, then its values.
      std::size_t
      get_count(std::istream &stream)
      {
        std::size_t n = 0;
        get(stream, n);
        return n;
      }

      void
      get_values(std::istream &stream, double *values, const std::size_t n)
      {
        io::read_bytes(stream, values, n * sizeof(double), source);
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

      constexpr std::size_t doubles_per_cell
        = sizeof(fe::EnhancedParameters) / sizeof(double);
      static_assert(sizeof(fe::EnhancedParameters)
                      == doubles_per_cell * sizeof(double),
                    "EnhancedParameters holds doubles only");

      void
      put_vector(std::ostream &stream, const Vector<double> &vector)
      {
        put_doubles(stream, vector.begin(), vector.size());
      }

      void
      get_vector(std::istream &stream, Vector<double> &vector)
      {
        vector.reinit(get_count(stream));
        get_values(stream, vector.begin(), vector.size());
      }
    } // namespace


    void
    SimulationState::write(std::ostream &stream) const
    {
      stream.write(tag, sizeof(tag));
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
      std::vector<double> points(doubles_per_point * history.size());
      for (std::size_t q = 0; q < history.size(); ++q)
        pack(history[q], &points[doubles_per_point * q]);
      put_doubles(stream, points.data(), points.size());
      put(stream, enhanced_parameters.size());
      for (const fe::EnhancedParameters &cell : enhanced_parameters)
        stream.write(reinterpret_cast<const char *>(&cell), sizeof(cell));
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
      char read_tag[sizeof(tag)] = {};
      stream.read(read_tag, sizeof(tag));
      const bool with_release = stream && std::string(read_tag) == tag;
      const bool with_stages
        = with_release
          || (stream && std::string(read_tag) == tag_before_release);
      if (!with_stages
          && (!stream || std::string(read_tag) != tag_without_stages))
        throw std::runtime_error("simulation state: not a deepdraw state");
      get(stream, load);
      get(stream, last_load_increment);
      get(stream, increment_number);
      std::size_t n = get_count(stream);
      if (n % 3 != 0)
        throw std::runtime_error("simulation state: bad vertex block");
      vertices.resize(n / 3);
      get_values(stream, reinterpret_cast<double *>(vertices.data()), n);
      get_vector(stream, total_displacement);
      get_vector(stream, converged_solution);
      get_vector(stream, previous_converged_solution);
      n = get_count(stream);
      if (n % doubles_per_point != 0)
        throw std::runtime_error("simulation state: bad history block");
      std::vector<double> points(n);
      get_values(stream, points.data(), n);
      history.resize(n / doubles_per_point);
      for (std::size_t q = 0; q < history.size(); ++q)
        unpack(&points[doubles_per_point * q], history[q]);
      enhanced_parameters.resize(get_count(stream));
      for (fe::EnhancedParameters &cell : enhanced_parameters)
      {
        io::read_bytes(stream, &cell, sizeof(cell), source);
      }
      get(stream, next_increment);
      for (auto *bytes : {&contact.pair_open, &contact.pair_status})
      {
        bytes->resize(get_count(stream));
        io::read_bytes(stream, bytes->data(), bytes->size(), source);
      }
      contact.tool_position.resize(get_count(stream));
      get_values(stream,
                 contact.tool_position.data(),
                 contact.tool_position.size());
      const std::size_t n_cycles = get_count(stream);
      if (n_cycles > 100000)
        throw std::runtime_error("simulation state: bad refinement block");
      refinements.resize(n_cycles);
      for (auto &cycle : refinements)
      {
        const std::size_t n_cells = get_count(stream);
        if (n_cells > (std::size_t(1) << 32))
          throw std::runtime_error("simulation state: bad refinement block");
        cycle.resize(n_cells);
        io::read_bytes(stream,
                       cycle.data(),
                       cycle.size() * sizeof(cycle[0]),
                       source);
      }
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
      get(stream, stage);
      unsigned char completed = 0;
      get(stream, completed);
      stage_completed = completed != 0;
      get(stream, stage_force_scale);
      for (auto *values : {&contact.tool_origin, &contact.tool_translation})
      {
        values->resize(get_count(stream));
        get_values(stream, values->data(), values->size());
      }
      if (!with_release)
        return;
      get(stream, end_force_scale);
      get_vector(stream, release_loads);
      const std::size_t n_supports = get_count(stream);
      if (n_supports > 100000)
        throw std::runtime_error("simulation state: bad support block");
      release_support_vertices.resize(n_supports);
      io::read_bytes(stream,
                     release_support_vertices.data(),
                     n_supports * sizeof(unsigned int),
                     source);
      get_vector(stream, release_start_displacement);
    }
  } // namespace state
} // namespace deepdraw
