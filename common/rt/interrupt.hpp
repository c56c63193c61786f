// Ctrl-C during a render: the first SIGINT asks the render loop to stop after the tile it is on (so the
// image so far can be saved, marked partial); a second one exits at once.
#pragma once

namespace rt {

void install_interrupt_handler();
bool interrupt_requested();
// For tests: as if the user had pressed Ctrl-C (or, with false, as if not).
void set_interrupt_requested(bool requested);

}  // namespace rt
