#include <algorithm>
#include <deepdraw/parallel/ranks.h>
#include <deepdraw/solver/mumps_factorization.h>
#include <exception>
#include <mpi.h>
#include <stdexcept>
#include <string>

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


    MumpsFactorization::MumpsFactorization(const bool scale)
    {
      int initialized = 0;
      MPI_Initialized(&initialized);
      if (!initialized)
        throw std::runtime_error("MUMPS needs MPI to be initialised");
      data = DMUMPS_STRUC_C();
      // Under mpirun MUMPS factorises across all the ranks (D199).
      distributed       = parallel::n_ranks() > 1;
      data.comm_fortran = static_cast<MUMPS_INT>(
        MPI_Comm_c2f(distributed ? MPI_COMM_WORLD : MPI_COMM_SELF));
      data.par = 1; // the host works
      data.sym = 0; // unsymmetric (contact rows, D90)
      data.job = -1;
      dmumps_c(&data);
      // Silent: no messages, statistics or warnings on the terminal.
      data.icntl[index(1)] = -1;
      data.icntl[index(2)] = -1;
      data.icntl[index(3)] = -1;
      data.icntl[index(4)] = 0;
      // Working space beyond the analysis' estimate, in percent: delayed
      // pivots of the whole (uncondensed) system's multiplier rows need
      // more than the default 20 (D64 used 400 through Amesos).
      data.icntl[index(14)] = 100;
      // No column permutation from the values (MC64): the analysis then
      // depends on the pattern alone, and LinearSolver keeps it from one
      // increment to the next without changing the arithmetic (D97).
      data.icntl[index(6)] = 0;
      // No row and column scaling where the caller knows the matrix to be
      // well scaled (the condensed displacement system): MUMPS' iterative
      // scaling is otherwise recomputed in every factorisation (D98).
      if (!scale)
        data.icntl[index(8)] = 0;
      // Each rank gives the rows it owns (distributed assembled input,
      // D214). The right-hand sides and solutions stay on the host.
      if (distributed)
        data.icntl[index(18)] = 3;
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
    }


    void
    MumpsFactorization::run(const int job)
    {
      for (unsigned int attempt = 0;; ++attempt)
      {
        data.job = job;
        dmumps_c(&data);
        const int status = data.infog[index(1)];
        if (status >= 0)
          return;
        if ((status == -8 || status == -9) && attempt < 3)
        {
          data.icntl[index(14)] *= 2;
          continue;
        }
        const int         detail = data.infog[index(2)];
        const std::string memory = memory_failure(status, detail);
        if (!memory.empty())
          throw MumpsMemoryError(
            "the linear solver MUMPS ran out of memory in job "
            + std::to_string(job) + " (INFOG(1) = " + std::to_string(status)
            + ", INFOG(2) = " + std::to_string(detail) + ": " + memory
            + ", with ICNTL(14) = " + std::to_string(data.icntl[index(14)])
            + " % extra workspace); a smaller increment would not help: use "
              "a coarser mesh or a machine with more memory");
        throw std::runtime_error(
          "MUMPS failed in job " + std::to_string(job)
          + " (INFOG(1) = " + std::to_string(status)
          + ", INFOG(2) = " + std::to_string(data.infog[index(2)])
          + (status == -10 ? ": the matrix is numerically singular" : "")
          + ")");
      }
    }


    void
    MumpsFactorization::factorize(const SparseMatrix<double> &matrix,
                                  const std::vector<bool>    &owned)
    {
      const SparsityPattern &pattern = matrix.get_sparsity_pattern();
      bool new_pattern = !analysed || !analysed_pattern.matches(pattern);
      // The analysis is collective: the ranks agree on a new one.
      if (distributed)
        new_pattern = parallel::maximum(new_pattern ? 1 : 0) == 1;
      if (new_pattern)
        set_up_pattern(pattern, owned);
      // On one rank the values in storage order are the coordinate entries
      // of set_up_pattern: MUMPS reads them in place, during job 2 only.
      // The first stored entry is (0, 0): a square pattern stores the
      // diagonal first (checked in set_up_pattern). Under mpirun the owned
      // rows' values are copied out.
      double *values = pattern.n_nonzero_elements() == 0
                         ? nullptr
                         : const_cast<double *>(&matrix(0, 0));
      if (distributed)
      {
        for (std::size_t k = 0; k < local_positions.size(); ++k)
          local_values[k] = values[local_positions[k]];
        data.a_loc = local_values.empty() ? nullptr : local_values.data();
      }
      else
        data.a = row_index.empty() ? nullptr : values;
      if (!analysed)
        analyse();
      run(2);
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
    void
    MumpsFactorization::analyse()
    {
      candidates.clear();
      for (const int ordering : {0, 4})
      {
        if (ordering == 4 && data.n < pord_smallest_system)
          continue;
        data.icntl[index(7)] = ordering;
        run(1);
        candidates.push_back({ordering, data.rinfog[index(1)]});
      }
      const auto best
        = std::min_element(candidates.begin(),
                           candidates.end(),
                           [](const OrderingCandidate &a,
                              const OrderingCandidate &b)
                           { return a.estimated_flops < b.estimated_flops; });
      if (best->ordering != candidates.back().ordering)
      {
        data.icntl[index(7)] = best->ordering;
        run(1);
      }
      analysed = true;
      ++symbolic_analyses;
    }


    int
    MumpsFactorization::ordering() const
    {
      return data.infog[index(7)];
    }


    const std::vector<MumpsFactorization::OrderingCandidate> &
    MumpsFactorization::ordering_candidates() const
    {
      return candidates;
    }


    void
    MumpsFactorization::solve(std::vector<Vector<double>> &rhs_and_solutions)
    {
      const std::size_t n = analysed ? static_cast<std::size_t>(data.n) : 0;
      for (const Vector<double> &column : rhs_and_solutions)
        if (!analysed || column.size() != n)
          throw std::runtime_error(
            "MUMPS: solve() needs a factorisation of a matrix of the "
            "right-hand side's size");
      right_hand_sides.resize(n * rhs_and_solutions.size());
      for (std::size_t c = 0; c < rhs_and_solutions.size(); ++c)
        std::copy(rhs_and_solutions[c].begin(),
                  rhs_and_solutions[c].end(),
                  right_hand_sides.begin() + c * n);
      data.rhs  = right_hand_sides.data();
      data.nrhs = rhs_and_solutions.size();
      data.lrhs = n;
      run(3);
      // The solution is on the host.
      if (distributed)
        parallel::broadcast(right_hand_sides.data(),
                            right_hand_sides.size() * sizeof(double));
      for (std::size_t c = 0; c < rhs_and_solutions.size(); ++c)
        std::copy(right_hand_sides.begin() + c * n,
                  right_hand_sides.begin() + (c + 1) * n,
                  rhs_and_solutions[c].begin());
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
      analysed = false;
    }


    unsigned int
    MumpsFactorization::n_symbolic_analyses() const
    {
      return symbolic_analyses;
    }


    double
    MumpsFactorization::factorization_flops() const
    {
      return data.rinfog[index(3)];
    }


    double
    MumpsFactorization::factor_entries() const
    {
      const int entries = data.infog[index(29)];
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
      data.n = n_rows;
      if (distributed)
      {
        data.nnz_loc = row_index.size();
        data.irn_loc = row_index.data();
        data.jcn_loc = column_index.data();
      }
      else
      {
        data.nnz = row_index.size();
        data.irn = row_index.data();
        data.jcn = column_index.data();
      }
      analysed = false;
    }
  } // namespace solver
} // namespace deepdraw
