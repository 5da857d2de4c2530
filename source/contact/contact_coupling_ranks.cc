// ContactCoupling, part 7: the contact pairs under mpirun (D216). Each rank
// evaluates the pairs of the nodes whose rows it owns; every rank then
// receives the others' outcomes, so that it adds every pair to its rows as
// one rank does. Most pairs are open (on 100 x 100 x 2 at 8 mm about 2 000
// of 30 603 are closed): an open pair's result follows from its multiplier
// and augmentation, and only its gap for the output is sent.
#include <cstring>
#include <deepdraw/contact/contact_coupling.h>
#include <deepdraw/parallel/ranks.h>

namespace deepdraw
{
  namespace contact
  {
    namespace
    {
      // Flags: found, and whether the whole result follows.
      constexpr unsigned char found_flag  = 1;
      constexpr unsigned char closed_flag = 2;

      template <typename T>
      void
      append(std::vector<char> &buffer, const T &value)
      {
        const char *bytes = reinterpret_cast<const char *>(&value);
        buffer.insert(buffer.end(), bytes, bytes + sizeof(T));
      }

      template <typename T>
      const char *
      read(const char *next, T &value)
      {
        std::memcpy(&value, next, sizeof(T));
        return next + sizeof(T);
      }
    } // namespace


    void
    ContactCoupling::exchange_pair_outcomes(const Vector<double> &solution)
    {
      if (pair_owners.empty())
        return;
      const unsigned int me = parallel::this_rank();
      std::vector<char>  buffer;
      for (unsigned int rank = 0; rank < parallel::n_ranks(); ++rank)
      {
        buffer.clear();
        if (rank == me)
          for (std::size_t p = 0; p < pairs.size(); ++p)
            if (pair_owners[p] == me)
            {
              const Pair &pair   = pairs[p];
              const bool  closed = pair.result.state != ContactState::open;
              append(buffer,
                     static_cast<unsigned char>((pair.found ? found_flag : 0)
                                                | (closed ? closed_flag : 0)));
              if (closed)
                append(buffer, pair.result);
              else
                append(buffer, pair.result.normal_gap);
            }
        unsigned long long size = buffer.size();
        parallel::broadcast(&size, sizeof(size), rank);
        buffer.resize(size);
        parallel::broadcast(buffer.data(), size, rank);
        if (rank == me)
          continue;
        const char *next = buffer.data();
        for (std::size_t p = 0; p < pairs.size(); ++p)
          if (pair_owners[p] == rank)
          {
            Pair         &pair  = pairs[p];
            unsigned char flags = 0;
            next                = read(next, flags);
            pair.found          = (flags & found_flag) != 0;
            if ((flags & closed_flag) != 0)
            {
              next = read(next, pair.result);
              continue;
            }
            // Open: the law's open branch and the pair beyond the search
            // distance alike (evaluate_pair()).
            Tensor<1, 3> lambda;
            double       normal_gap = 0.;
            for (unsigned int c = 0; c < 3; ++c)
              lambda[c] = solution[pair.first_multiplier + c];
            next = read(next, normal_gap);
            pair.result
              = open_contact_pair(lambda, pair.augmentation, normal_gap);
          }
      }
    }
  } // namespace contact
} // namespace deepdraw
