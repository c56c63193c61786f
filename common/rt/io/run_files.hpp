// The files a run (or a tool) reads and writes, kept apart: no output may be an input, and no two outputs
// may be one file, whether by the same name or by links to one file. Checked before any work, with every
// output probed, so that nothing the user gave is replaced and no output is lost under another.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rt {

// Two paths name one file: the same path, or links to one file.
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

// A file a run reads or writes: the flag that named it, and what a message calls it.
struct RunFile {
    std::string flag;            // "--out"
    std::string what;            // "the partial image"
    std::filesystem::path path;  // x.partial.png
};

// Throws InputError when an output is one of the inputs or another output, one line naming the output's
// flag and both files: "--heat: the heat maps h.partial.png is the partial image h.partial.png: one would
// replace the other; give another name". Each output is compared with the inputs, then the outputs before it.
void check_files_apart(const std::vector<RunFile>& outputs, const std::vector<RunFile>& inputs);

// check_files_apart, then each output probed (check_writable, image_io.hpp): an InputError names its flag.
void check_outputs(const std::vector<RunFile>& outputs, const std::vector<RunFile>& inputs);

}  // namespace rt
