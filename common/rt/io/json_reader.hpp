// Parsing a scene file's JSON text strictly: a key given twice in one object (two "radius", two materials of
// one name) is refused, naming the key and both places, where nlohmann's parser would keep the last value in
// silence; a syntax error is one whole line.
#pragma once

#include <nlohmann/json.hpp>
#include <string_view>

namespace rt {

// Throws InputError "not valid JSON: ..." or "PLACE: key "K" given twice, at line L1, column C1 and line L2,
// column C2" (the caller puts the file's name before it).
nlohmann::json parse_json_strictly(std::string_view text);

}  // namespace rt
