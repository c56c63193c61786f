// Adding the films of a render's pieces into the film of the whole (rt_merge): the pieces must be of one
// render (the same FilmIdentity), each complete, and together take every sample 0:N exactly once.
#pragma once

#include <string>
#include <vector>

#include "rt/io/film.hpp"

namespace rt {

struct FilmPiece {
    std::string name;  // for messages: the file it was read from
    Film film;
};

// The pieces summed (in the order of their ranges: integer sums, the same bits in any order). Throws
// InputError naming the offending piece: another render's, interrupted, a gap, an overlap.
Film merge_films(std::vector<FilmPiece> pieces);

}  // namespace rt
