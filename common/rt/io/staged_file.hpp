// A file written under a staging name beside the file it will become, then renamed into place: the final
// name holds either the earlier file or the finished one, never half a file.
//
// A staging name is ".rt-<pid>-<n>.staging" in the target's folder: unique per process (the process id and a
// counter; created exclusively, so no one else's file is ever opened or removed) and at most 40 bytes,
// however long the target's own name. Each is removed by the destructor unless committed, and by
// remove_staged_files_now() (async-signal-safe) from a signal handler that ends the process.
#pragma once

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <vector>

namespace rt {

class StagedFile {
  public:
    // Creates the staging file beside `target`, open for writing. Throws InputError naming the target and
    // why when it is a folder, or its folder does not take a new file.
    explicit StagedFile(std::filesystem::path target);
    StagedFile(const StagedFile&) = delete;
    StagedFile& operator=(const StagedFile&) = delete;
    ~StagedFile();

    std::FILE* file() { return file_; }
    const std::filesystem::path& target() const { return target_; }
    // Flushes and closes the file; false if a write, the flush or the close failed (errno says why).
    bool close();
    // Renames the closed staging file over the target. Throws std::runtime_error when that fails.
    void commit();

  private:
    std::filesystem::path target_;
    std::filesystem::path staging_;
    std::FILE* file_ = nullptr;
    int slot_ = -1;  // in the table of staging files that remove_staged_files_now() removes
    bool committed_ = false;
};

// Writes through `write_to(file)` into the staging file and closes it; throws std::runtime_error naming the
// target when a write, the flush or the close failed (the staging file is then removed by its destructor,
// and an earlier file at the target is left as it was).
void write_staged(StagedFile& staged, const std::function<bool(std::FILE*)>& write_to);
// Renames every staged file into place with every signal held back (interrupt.hpp), so that a signal that
// ends the process at once cannot fall between two renames (a new PFM beside an old PNG): all or none.
void commit_together(const std::vector<StagedFile*>& files);
// fwrite that says whether every byte was written.
bool write_bytes(std::FILE* file, const void* data, std::size_t size);

// Removes every staging file of this process that is not yet committed. Async-signal-safe (unlink only).
void remove_staged_files_now();

}  // namespace rt
