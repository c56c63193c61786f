#include "rt/run/mpi_split.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "rt/core/errors.hpp"

#ifdef RT_HAVE_MPI
#include <mpi.h>
#endif

namespace rt {
namespace {

// The job's size when a launcher started this process (Open MPI's mpirun, or a PMI launcher such as srun),
// else 0.
int launcher_size(const char* open_mpi, const char* pmi) {
    for (const char* name : {open_mpi, pmi}) {
        if (const char* value = std::getenv(name)) return std::max(1, std::atoi(value));
    }
    return 0;
}

#ifdef RT_HAVE_MPI
// Rank 0 gets the sums added pixel by pixel, in slices (an MPI count is an int).
extern "C" void add_pixel_sums(void* in, void* inout, int* length, MPI_Datatype*) {
    const auto* from = static_cast<const PixelSum*>(in);
    auto* to = static_cast<PixelSum*>(inout);
    for (int i = 0; i < *length; ++i) to[i].add(from[i]);
}

// The same for the pixels' high parts (pixel_sums.hpp), which a PixelSum keeps out of line.
extern "C" void add_high_parts(void* in, void* inout, int* length, MPI_Datatype*) {
    const auto* from = static_cast<const HighParts*>(in);
    auto* to = static_cast<HighParts*>(inout);
    for (int i = 0; i < *length; ++i)
        for (std::size_t c = 0; c < 3; ++c) to[i][c] += from[i][c];
}

// Reduces `data` (n items of `bytes` each, rank 0's in place) with `add` onto rank 0, in slices (an MPI count
// is an int).
void reduce_to_root(void* data, std::size_t n, std::size_t bytes, MPI_User_function* add, bool root) {
    MPI_Datatype item;
    MPI_Type_contiguous(int(bytes), MPI_BYTE, &item);
    MPI_Type_commit(&item);
    MPI_Op op;
    MPI_Op_create(add, 1, &op);
    constexpr std::size_t kSlice = 1 << 20;
    for (std::size_t at = 0; at < n; at += kSlice) {
        char* slice = static_cast<char*>(data) + at * bytes;
        const int count = int(std::min(kSlice, n - at));
        MPI_Reduce(root ? MPI_IN_PLACE : slice, root ? slice : nullptr, count, item, op, 0, MPI_COMM_WORLD);
    }
    MPI_Op_free(&op);
    MPI_Type_free(&item);
}
#endif

}  // namespace

MpiSession::MpiSession() {
    const int launched = launcher_size("OMPI_COMM_WORLD_SIZE", "PMI_SIZE");
#ifdef RT_HAVE_MPI
    if (launched == 0) return;
    MPI_Init(nullptr, nullptr);
    joined_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    MPI_Comm local;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &local);
    MPI_Comm_size(local, &local_size_);
    MPI_Comm_free(&local);
#else
    if (launched > 1) {
        throw InputError("started by mpirun with " + std::to_string(launched) +
                         " processes, but this build has no MPI: install libopenmpi-dev and openmpi-bin, "
                         "then configure again");
    }
#endif
}

MpiSession::~MpiSession() {
#ifdef RT_HAVE_MPI
    if (joined_) MPI_Finalize();
#endif
}

void MpiSession::gather(RenderResult& result) const {
    if (size_ == 1) return;
#ifdef RT_HAVE_MPI
    // A pixel's high parts are behind a pointer, which means nothing to another process: when any rank has
    // one, they are taken out (leaving plain bytes) and reduced on their own.
    std::vector<PixelSum>& sums = result.sums.pixels();
    const bool any_high = on_any_rank(std::any_of(sums.begin(), sums.end(),
                                                  [](const PixelSum& p) { return p.high() != HighParts{}; }));
    std::vector<HighParts> high;
    if (any_high) {
        high.reserve(sums.size());
        for (PixelSum& p : sums) high.push_back(p.take_high());
    }
    reduce_to_root(sums.data(), sums.size(), sizeof(PixelSum), add_pixel_sums, is_root());
    if (any_high) {
        reduce_to_root(high.data(), high.size(), sizeof(HighParts), add_high_parts, is_root());
        for (std::size_t i = 0; i < sums.size(); ++i) sums[i].add_high(high[i]);
    }
    auto sum_in_place = [&](void* data, int n, MPI_Datatype type, MPI_Op op) {
        MPI_Reduce(is_root() ? MPI_IN_PLACE : data, is_root() ? data : nullptr, n, type, op, 0,
                   MPI_COMM_WORLD);
    };
    sum_in_place(result.rays.count.data(), kRayKindCount, MPI_UINT64_T, MPI_SUM);
    sum_in_place(&result.samples, 1, MPI_UINT64_T, MPI_SUM);
    sum_in_place(&result.seconds, 1, MPI_DOUBLE, MPI_MAX);
    result.interrupted = on_any_rank(result.interrupted);
    if (is_root()) {
        result.image = result.sums.mean_image();
        result.samples_per_pixel = int(result.sums.min_count());
    }
#else
    (void)result;
#endif
}

bool MpiSession::on_any_rank(bool flag) const {
#ifdef RT_HAVE_MPI
    if (size_ > 1) {
        int any = flag ? 1 : 0;
        MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD);
        return any != 0;
    }
#endif
    return flag;
}

void MpiSession::abort(int status) const {
#ifdef RT_HAVE_MPI
    if (joined_) MPI_Abort(MPI_COMM_WORLD, status);
#endif
    std::exit(status);
}

}  // namespace rt
