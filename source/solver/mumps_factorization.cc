#include <algorithm>
#include <deepdraw/parallel/ranks.h>
#include <deepdraw/solver/mumps_factorization.h>
#include <exception>
#include <mpi.h>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace deepdraw
{
  namespace solver
  {
    namespace
    {
      // MUMPS' arrays are 1-based in the documentation: ICNTL(i) is
      // icntl[i - 1].
      constexpr int
      index(const int fortran_index)
      {
        return fortran_index - 1;
      }

      // What a memory or workspace failure of MUMPS is (its user guide,
      // "Error diagnostics"); "" for other failures.
      std::string
      memory_failure(const int status, const int detail)
      {
        switch (status)
        {
          case -7:
          case -13:
            return "an allocation of "
                   + (detail < 0 ? std::to_string(-detail) + " million"
                                 : std::to_string(detail))
                   + " entries failed: not enough memory";
          case -8:
          case -14:
          case -15:
            return "its integer workspace is too small";
          case -9:
          case -11:
          case -12:
            return "its real workspace is too small";
          case -17:
          case -20:
            return "an internal buffer is too small";
          case -19:
            return "the memory limit ICNTL(23) is too small";
          default:
            return "";
        }
      }
    } // namespace


    namespace
    {
      void
      call(DMUMPS_STRUC_C &instance)
      {
        dmumps_c(&instance);
      }

      void
      call(SMUMPS_STRUC_C &instance)
      {
        smumps_c(&instance);
      }
    } // namespace


    MumpsFactorization::MumpsFactorization(const bool scale)
        : scale(scale)
    {
      int initialized = 0;
      MPI_Initialized(&initialized);
      if (!initialized)
        throw std::runtime_error("MUMPS needs MPI to be initialised");
      // Under mpirun MUMPS factorises across all the ranks (D199).
      distributed = parallel::n_ranks() > 1;
      data        = DMUMPS_STRUC_C();
      configure(data, scale);
    }


    template <typename Instance>
    void
    MumpsFactorization::configure(Instance &instance, const bool scale)
    {
      instance.comm_fortran = static_cast<MUMPS_INT>(
        MPI_Comm_c2f(distributed ? MPI_COMM_WORLD : MPI_COMM_SELF));
      instance.par = 1; // the host works
      instance.sym = 0; // unsymmetric (contact rows, D90)
      instance.job = -1;
      call(instance);
      // Silent: no messages, statistics or warnings on the terminal.
      instance.icntl[index(1)] = -1;
      instance.icntl[index(2)] = -1;
      instance.icntl[index(3)] = -1;
      instance.icntl[index(4)] = 0;
      // Working space beyond the analysis' estimate, in percent: delayed
      // pivots of the whole (uncondensed) system's multiplier rows need
      // more than the default 20 (D64 used 400 through Amesos).
      instance.icntl[index(14)] = 100;
      // No column permutation from the values (MC64): the analysis then
      // depends on the pattern alone, and LinearSolver keeps it from one
      // increment to the next without changing the arithmetic (D97).
      instance.icntl[index(6)] = 0;
      // No row and column scaling where the caller knows the matrix to be
      // well scaled (the condensed displacement system): MUMPS' iterative
      // scaling is otherwise recomputed in every factorisation (D98).
      if (!scale)
        instance.icntl[index(8)] = 0;
      // Each rank gives the rows it owns (distributed assembled input,
      // D214). The right-hand sides and solutions stay on the host.
      if (distributed)
        instance.icntl[index(18)] = 3;
    }


    MumpsFactorization::~MumpsFactorization()
    {
      // Releasing a distributed instance is collective: a rank leaving on
      // an exception (another rank may be elsewhere) leaves it to the end
      // of the process.
      if (distributed && std::uncaught_exceptions() > 0)
        return;
      data.job = -2;
      dmumps_c(&data);
      if (single_data != nullptr)
      {
        single_data->job = -2;
        smumps_c(single_data.get());
      }
    }


    template <typename Instance>
    void
    MumpsFactorization::run(Instance &instance, const int job)
    {
      for (unsigned int attempt = 0;; ++attempt)
      {
        instance.job = job;
        call(instance);
        const int status = instance.infog[index(1)];
        if (status >= 0)
          return;
        if ((status == -8 || status == -9) && attempt < 3)
        {
          instance.icntl[index(14)] *= 2;
          continue;
        }
        const int         detail = instance.infog[index(2)];
        const std::string memory = memory_failure(status, detail);
        if (!memory.empty())
          throw MumpsMemoryError(
            "the linear solver MUMPS ran out of memory in job "
            + std::to_string(job) + " (INFOG(1) = " + std::to_string(status)
            + ", INFOG(2) = " + std::to_string(detail) + ": " + memory
            + ", with ICNTL(14) = " + std::to_string(instance.icntl[index(14)])
            + " % extra workspace); a smaller increment would not help: use "
              "a coarser mesh or a machine with more memory");
        throw std::runtime_error(
          "MUMPS failed in job " + std::to_string(job) + " (INFOG(1) = "
          + std::to_string(status) + ", INFOG(2) = " + std::to_string(detail)
          + (status == -10 ? ": the matrix is numerically singular" : "")
          + ")");
      }
    }


    void
    MumpsFactorization::factorize(const SparseMatrix<double> &matrix,
                                  const std::vector<bool>    &owned,
                                  const FactorPrecision       precision)
    {
      const SparsityPattern &pattern = matrix.get_sparsity_pattern();
      bool new_pattern = !has_pattern || !analysed_pattern.matches(pattern);
      // The analysis is collective: the ranks agree on a new one.
      if (distributed)
        new_pattern = parallel::maximum(new_pattern ? 1 : 0) == 1;
      if (new_pattern)
        set_up_pattern(pattern, owned);
      last_precision = precision;
      hold_one_precision(precision);
      give_values(matrix);
      if (precision == FactorPrecision::double_precision)
      {
        if (!analysed)
          analyse(data);
        analysed = true;
        run(data, 2);
        double_factors_held = true;
        return;
      }
      if (!single_analysed)
        analyse(*single_data);
      single_analysed = true;
      run(*single_data, 2);
    }


    // The two precisions' factors are never held together: the other
    // precision's instance, with its factors and analysis, is released
    // (MUMPS 5.5 cannot free factors alone). A switch costs an analysis; it
    // happens at a stage's first increment and where a refinement fails (D226).
    void
    MumpsFactorization::hold_one_precision(const FactorPrecision precision)
    {
      if (precision == FactorPrecision::double_precision)
      {
        if (single_data != nullptr)
        {
          single_data->job = -2;
          smumps_c(single_data.get());
          single_data.reset();
        }
        single_analysed = false;
        return;
      }
      if (double_factors_held)
      {
        data.job = -2;
        dmumps_c(&data);
        data = DMUMPS_STRUC_C();
        configure(data, scale);
        give_pattern(data);
        analysed            = false;
        double_factors_held = false;
      }
      if (single_data == nullptr)
      {
        single_data  = std::make_unique<SMUMPS_STRUC_C>();
        *single_data = SMUMPS_STRUC_C();
        configure(*single_data, scale);
        give_pattern(*single_data);
        single_analysed = false;
      }
    }


    template <typename Instance>
    void
    MumpsFactorization::give_pattern(Instance &instance) const
    {
      instance.n = analysed_pattern_rows;
      if (distributed)
      {
        instance.nnz_loc = row_index.size();
        instance.irn_loc = const_cast<int *>(row_index.data());
        instance.jcn_loc = const_cast<int *>(column_index.data());
      }
      else
      {
        instance.nnz = row_index.size();
        instance.irn = const_cast<int *>(row_index.data());
        instance.jcn = const_cast<int *>(column_index.data());
      }
    }


    void
    MumpsFactorization::give_values(const SparseMatrix<double> &matrix)
    {
      // On one rank the values in storage order are the coordinate entries
      // of set_up_pattern: MUMPS reads them in place, during job 2 only.
      // The first stored entry is (0, 0): a square pattern stores the
      // diagonal first (checked in set_up_pattern). Under mpirun the owned
      // rows' values are copied out, and single precision takes a copy
      // rounded to float.
      const SparsityPattern &pattern = matrix.get_sparsity_pattern();
      double                *values  = pattern.n_nonzero_elements() == 0
                                         ? nullptr
                                         : const_cast<double *>(&matrix(0, 0));
      if (distributed)
      {
        for (std::size_t k = 0; k < local_positions.size(); ++k)
          local_values[k] = values[local_positions[k]];
        values = local_values.empty() ? nullptr : local_values.data();
      }
      else if (row_index.empty())
        values = nullptr;
      if (last_precision == FactorPrecision::double_precision)
      {
        (distributed ? data.a_loc : data.a) = values;
        return;
      }
      const std::size_t n_values
        = distributed ? local_values.size() : row_index.size();
      single_values.assign(values, values + n_values);
      float *single = single_values.empty() ? nullptr : single_values.data();
      if (distributed)
        single_data->a_loc = single;
      else
        single_data->a = single;
    }


    namespace
    {
      constexpr int pord_smallest_system = 1000;
    } // namespace


    // The orderings Debian's MUMPS has (no METIS or SCOTCH): ICNTL(7) = 0
    // (AMD) and 4 (PORD, MUMPS' own choice without them). Which needs
    // fewer operations depends on the mesh: AMD 13 % fewer on the
    // reference sheet, PORD 11 % fewer on 100 x 100 x 2 (D98). The
    // analysis is cheap against the factorisations it serves (D97), so
    // each is tried and the one with the fewer estimated operations
    // (RINFOG(1)) kept. PORD is not tried on systems below
    // pord_smallest_system unknowns: on tiny graphs it ends the process
    // ("no valid number of stages in multisector", a one-cell sheet), and
    // AMD serves them as well (D186).
    template <typename Instance>
    void
    MumpsFactorization::analyse(Instance &instance)
    {
      candidates.clear();
      for (const int ordering : {0, 4})
      {
        if (ordering == 4 && instance.n < pord_smallest_system)
          continue;
        instance.icntl[index(7)] = ordering;
        run(instance, 1);
        candidates.push_back({ordering, instance.rinfog[index(1)]});
      }
      const auto best
        = std::min_element(candidates.begin(),
                           candidates.end(),
                           [](const OrderingCandidate &a,
                              const OrderingCandidate &b)
                           { return a.estimated_flops < b.estimated_flops; });
      if (best->ordering != candidates.back().ordering)
      {
        instance.icntl[index(7)] = best->ordering;
        run(instance, 1);
      }
      ++symbolic_analyses;
    }


    int
    MumpsFactorization::ordering() const
    {
      return last_precision == FactorPrecision::double_precision
               ? data.infog[index(7)]
               : single_data->infog[index(7)];
    }


    FactorPrecision
    MumpsFactorization::precision() const
    {
      return last_precision;
    }


    const std::vector<MumpsFactorization::OrderingCandidate> &
    MumpsFactorization::ordering_candidates() const
    {
      return candidates;
    }


    void
    MumpsFactorization::solve(std::vector<Vector<double>> &rhs_and_solutions)
    {
      const bool factorised
        = last_precision == FactorPrecision::double_precision ? analysed
                                                              : single_analysed;
      const std::size_t n = factorised ? static_cast<std::size_t>(data.n) : 0;
      for (const Vector<double> &column : rhs_and_solutions)
        if (!factorised || column.size() != n)
          throw std::runtime_error(
            "MUMPS: solve() needs a factorisation of a matrix of the "
            "right-hand side's size");
      right_hand_sides.resize(n * rhs_and_solutions.size());
      for (std::size_t c = 0; c < rhs_and_solutions.size(); ++c)
        std::copy(rhs_and_solutions[c].begin(),
                  rhs_and_solutions[c].end(),
                  right_hand_sides.begin() + c * n);
      if (last_precision == FactorPrecision::double_precision)
        solve_columns(data, rhs_and_solutions.size());
      else
      {
        // Rounded to float and back: the solve is an approximate inverse
        // either way (D226).
        single_right_hand_sides.assign(right_hand_sides.begin(),
                                       right_hand_sides.end());
        solve_columns(*single_data, rhs_and_solutions.size());
        std::copy(single_right_hand_sides.begin(),
                  single_right_hand_sides.end(),
                  right_hand_sides.begin());
      }
      // The solution is on the host.
      if (distributed)
        parallel::broadcast(right_hand_sides.data(),
                            right_hand_sides.size() * sizeof(double));
      for (std::size_t c = 0; c < rhs_and_solutions.size(); ++c)
        std::copy(right_hand_sides.begin() + c * n,
                  right_hand_sides.begin() + (c + 1) * n,
                  rhs_and_solutions[c].begin());
    }


    template <typename Instance>
    void
    MumpsFactorization::solve_columns(Instance         &instance,
                                      const std::size_t n_columns)
    {
      if constexpr (std::is_same_v<Instance, DMUMPS_STRUC_C>)
        instance.rhs = right_hand_sides.data();
      else
        instance.rhs = single_right_hand_sides.data();
      instance.nrhs = n_columns;
      instance.lrhs = data.n;
      run(instance, 3);
    }


    void
    MumpsFactorization::solve(const Vector<double> &rhs,
                              Vector<double>       &solution)
    {
      std::vector<Vector<double>> columns(1, rhs);
      solve(columns);
      solution = columns[0];
    }


    void
    MumpsFactorization::forget_analysis()
    {
      has_pattern     = false;
      analysed        = false;
      single_analysed = false;
    }


    unsigned int
    MumpsFactorization::n_symbolic_analyses() const
    {
      return symbolic_analyses;
    }


    double
    MumpsFactorization::factorization_flops() const
    {
      return last_precision == FactorPrecision::double_precision
               ? data.rinfog[index(3)]
               : single_data->rinfog[index(3)];
    }


    double
    MumpsFactorization::factor_entries() const
    {
      const int entries = last_precision == FactorPrecision::double_precision
                            ? data.infog[index(29)]
                            : single_data->infog[index(29)];
      // Negative: millions of entries (MUMPS' convention for large counts).
      return entries >= 0 ? entries : -1e6 * entries;
    }


    // Coordinate format in the storage order of the compressed pattern
    // (MUMPS accepts any order), which is that of the matrix's values.
    void
    MumpsFactorization::set_up_pattern(const SparsityPattern   &pattern,
                                       const std::vector<bool> &owned)
    {
      AssertThrow(pattern.is_compressed()
                    && pattern.n_rows() == pattern.n_cols()
                    && (pattern.n_rows() == 0
                        || pattern.begin(0)->column() == 0),
                  ExcMessage("MUMPS: a compressed square pattern is needed"));
      analysed_pattern.take(pattern);
      const std::size_t n_rows = pattern.n_rows();
      // Under mpirun each rank gives the rows it owns (D214); one rank gives
      // all, in the storage order of the values, which MUMPS reads in place.
      AssertThrow(!distributed || owned.size() == n_rows,
                  ExcMessage("MUMPS under mpirun: each rank gives the rows "
                             "it owns of a matrix split by rows"));
      row_index.clear();
      column_index.clear();
      local_positions.clear();
      for (types::global_dof_index i = 0; i < n_rows; ++i)
        if (!distributed || owned[i])
          for (auto entry = pattern.begin(i); entry != pattern.end(i); ++entry)
          {
            if (distributed)
              local_positions.push_back(entry->global_index());
            else
              AssertThrow(entry->global_index() == row_index.size(),
                          ExcInternalError());
            row_index.push_back(i + 1);
            column_index.push_back(entry->column() + 1);
          }
      local_values.resize(local_positions.size());
      analysed_pattern_rows = n_rows;
      give_pattern(data);
      if (single_data != nullptr)
        give_pattern(*single_data);
      has_pattern     = true;
      analysed        = false;
      single_analysed = false;
    }
  } // namespace solver
} // namespace deepdraw
