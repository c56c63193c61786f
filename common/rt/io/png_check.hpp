// What stb_image does not check in a PNG file, checked before its texels are used: every chunk's CRC-32 (a
// damaged file is refused, not decoded into wrong texels) and every pixel's palette index (stb_image reads
// an index past the palette from memory the palette never filled).
#pragma once

#include <string_view>

namespace rt {

// Throws InputError, without the file's name, at the first fault: "chunk IDAT at byte 33: its CRC does not
// match its data (the file is damaged)", "pixel (1, 0): its palette index is past the 2 colour(s) of the
// PLTE chunk", or the chunk that runs past the end of the file. A fault stb_image itself reports (a PLTE of
// the wrong length, no IHDR first) is left to it.
void check_png(std::string_view png);

}  // namespace rt
