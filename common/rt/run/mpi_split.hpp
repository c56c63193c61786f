// One render split among the processes of `mpirun -np K chNN_name ...`: each rank takes its share of the
// samples (split_range), and rank 0 adds every rank's exact sums (pixel_sums.hpp) into its own, so the image
// is the same bits as one process's. Without MPI at build time (CMake did not find it), a process is always
// alone, and one started by mpirun with K > 1 refuses to run rather than render the whole image K times.
#pragma once

#include "rt/render/render_loop.hpp"

namespace rt {

class MpiSession {
  public:
    // Joins the MPI job when mpirun (or srun) started this process; otherwise a session of one.
    MpiSession();
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool is_root() const { return rank_ == 0; }
    // Ranks of this job on this machine: they share its cores.
    int ranks_on_this_machine() const { return local_size_; }

    // Collective. Rank 0's result gets every rank's sums, rays and samples added to its own, the slowest
    // rank's time, and `interrupted` when any rank was; its image is then the mean of the sums. The other
    // ranks' results are left as they were.
    void gather(RenderResult& result) const;
    // Whether `flag` is true on any rank. Collective.
    bool on_any_rank(bool flag) const;
    // A failure on one rank ends them all (the others would wait in gather forever).
    [[noreturn]] void abort(int status) const;

  private:
    int rank_ = 0;
    int size_ = 1;
    int local_size_ = 1;
    bool joined_ = false;
};

}  // namespace rt
