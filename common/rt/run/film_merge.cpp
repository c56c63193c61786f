#include "rt/run/film_merge.hpp"

#include <algorithm>

#include "rt/core/errors.hpp"

namespace rt {

Film merge_films(std::vector<FilmPiece> pieces) {
    if (pieces.empty()) throw InputError("no pieces to merge");
    const FilmIdentity& expected = pieces.front().film.identity;
    for (const FilmPiece& piece : pieces) {
        const std::string difference = first_difference(expected, piece.film.identity);
        if (!difference.empty()) {
            throw InputError(piece.name + ": not a piece of the same render as " + pieces.front().name +
                             ": " + difference);
        }
        check_film_values(piece.film, piece.name);
        if (!piece.film.complete()) {
            throw InputError(piece.name + ": an interrupted render (some pixels have " +
                             std::to_string(piece.film.sums.min_count()) + " of its samples " +
                             to_string(piece.film.range) + "): finish it first with --resume " + piece.name);
        }
    }
    std::stable_sort(pieces.begin(), pieces.end(), [](const FilmPiece& a, const FilmPiece& b) {
        return a.film.range.first < b.film.range.first;
    });
    const int total = expected.samples_per_pixel;
    int covered = 0;  // samples 0 … covered − 1 are in the pieces so far
    const FilmPiece* previous = nullptr;
    for (const FilmPiece& piece : pieces) {
        const SampleRange r = piece.film.range;
        if (r.first > covered) {
            throw InputError(piece.name + ": takes samples " + to_string(r) + ", but samples " +
                             to_string({covered, r.first}) + " are in no piece" +
                             (previous ? " (the piece before is " + previous->name + ", " +
                                             to_string(previous->film.range) + ")"
                                       : std::string()));
        }
        if (r.first < covered) {
            throw InputError(piece.name + ": takes samples " + to_string(r) + ", which overlap " +
                             previous->name + " (" + to_string(previous->film.range) + ") at samples " +
                             to_string({r.first, std::min(covered, r.end)}));
        }
        covered = r.end;
        previous = &piece;
    }
    if (covered < total) {
        throw InputError(previous->name + ": the last piece ends at sample " + std::to_string(covered) +
                         ", but samples " + to_string({covered, total}) + " are in no piece");
    }
    Film whole{expected, {0, total}, PixelSums(expected.width, expected.height)};
    for (const FilmPiece& piece : pieces) whole.sums.add(piece.film.sums);
    return whole;
}

}  // namespace rt
