#include "rt/io/staged_file.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"

namespace rt {
namespace fs = std::filesystem;

namespace {

// The staging files of this process that exist and are not yet committed: fixed storage, so that a signal
// handler can walk it without allocating. A slot is claimed (`claimed`), filled, then published (`live`).
constexpr int kSlots = 16;
struct Slot {
    std::atomic<bool> claimed{false};
    std::atomic<bool> live{false};
    char path[4096];
};
std::array<Slot, kSlots> g_slots;
std::atomic<unsigned> g_counter{0};

int claim_slot(const std::string& path) {
    if (path.size() >= sizeof(Slot::path)) return -1;
    for (int i = 0; i < kSlots; ++i) {
        if (g_slots[std::size_t(i)].claimed.exchange(true)) continue;
        Slot& s = g_slots[std::size_t(i)];
        std::memcpy(s.path, path.c_str(), path.size() + 1);
        s.live.store(true);
        return i;
    }
    return -1;
}

void release_slot(int slot) {
    if (slot < 0) return;
    g_slots[std::size_t(slot)].live.store(false);
    g_slots[std::size_t(slot)].claimed.store(false);
}

std::string reason(int error) {
    return error != 0 ? " (" + std::string(std::strerror(error)) + ")" : "";
}

// Why `folder` takes no file, or nothing when it exists and is a folder.
std::string folder_problem(const fs::path& folder) {
    std::error_code ec;
    const fs::file_status status = fs::status(folder, ec);
    if (status.type() == fs::file_type::not_found) return "folder " + shown(folder) + " does not exist";
    if (ec) return "folder " + shown(folder) + " cannot be reached: " + ec.message();
    if (status.type() != fs::file_type::directory) return shown(folder) + " is a file, not a folder";
    return "";
}

}  // namespace

StagedFile::StagedFile(fs::path target) : target_(std::move(target)) {
    const fs::path folder = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
    const std::string where = shown(target_) + ": cannot be written: ";
    if (const std::string problem = folder_problem(folder); !problem.empty())
        throw InputError(where + problem);
    std::error_code ec;
    if (fs::is_directory(target_, ec)) throw InputError(where + "it is a folder");
    // Exclusive creation: a name some other file already has is skipped, never opened.
    for (int attempt = 0; attempt < 100; ++attempt) {
        const fs::path candidate = target_.has_parent_path() ? folder / "" : fs::path();
        staging_ = candidate.string() + ".rt-" + std::to_string(::getpid()) + "-" +
                   std::to_string(g_counter++) + ".staging";
        slot_ = claim_slot(staging_.string());
        if (slot_ < 0) throw std::runtime_error(where + "too many files staged at once");
        const int fd = ::open(staging_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            file_ = ::fdopen(fd, "wb");
            if (file_) return;
            ::close(fd);
            ::unlink(staging_.c_str());
        }
        const int error = errno;
        release_slot(slot_);
        slot_ = -1;
        if (error == EEXIST) continue;
        throw InputError(where + "folder " + shown(folder) + " does not take a new file" + reason(error));
    }
    throw InputError(where + "no free staging name in folder " + shown(folder));
}

StagedFile::~StagedFile() {
    if (file_) std::fclose(file_);
    if (!committed_) ::unlink(staging_.c_str());
    release_slot(slot_);
}

bool StagedFile::close() {
    if (!file_) return true;
    bool ok = std::fflush(file_) == 0 && !std::ferror(file_);
    const int error = errno;
    ok = std::fclose(file_) == 0 && ok;
    file_ = nullptr;
    if (!ok && error != 0) errno = error;
    return ok;
}

void StagedFile::commit() {
    if (file_ && !close()) {
        throw std::runtime_error(shown(target_) + ": could not write the file" + reason(errno) +
                                 "; an earlier file of that name is left as it was");
    }
    if (::rename(staging_.c_str(), target_.c_str()) != 0) {
        throw std::runtime_error(shown(target_) + ": could not rename the finished file into place" +
                                 reason(errno) + "; an earlier file of that name is left as it was");
    }
    committed_ = true;
    release_slot(slot_);
    slot_ = -1;
}

void write_staged(StagedFile& staged, const std::function<bool(std::FILE*)>& write_to) {
    errno = 0;
    bool ok = write_to(staged.file());
    const int error = errno;
    ok = staged.close() && ok;
    if (!ok) {
        throw std::runtime_error(shown(staged.target()) + ": could not write the file" +
                                 reason(error ? error : errno) +
                                 "; an earlier file of that name is left as it was");
    }
}

void commit_together(const std::vector<StagedFile*>& files) {
    sigset_t held, previous;
    sigfillset(&held);  // every signal that can be held back (not SIGKILL)
    pthread_sigmask(SIG_BLOCK, &held, &previous);
    try {
        for (StagedFile* f : files) f->commit();
    } catch (...) {
        pthread_sigmask(SIG_SETMASK, &previous, nullptr);
        throw;
    }
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
}

bool write_bytes(std::FILE* file, const void* data, std::size_t size) {
    return std::fwrite(data, 1, size, file) == size;
}

void remove_staged_files_now() {
    for (Slot& s : g_slots) {
        if (s.live.load()) ::unlink(s.path);
    }
}

}  // namespace rt
