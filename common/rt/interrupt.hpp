// Ctrl-C (SIGINT) or SIGTERM during a run. The first asks the render loop to stop after the sample each thread
// is on (so the image so far can be saved, marked partial), or, once the render is over, lets the files being
// written be finished; a second one removes every staging file and exits at once, writing nothing.
// The live view (live_view.hpp) also stops a render this way, without a signal, to render again with other knobs.
#pragma once

namespace rt {

// What a first signal interrupts, for the message it prints.
enum class InterruptPhase { kRendering, kWriting, kLive };

// Installs the handler for SIGINT and SIGTERM.
void install_interrupt_handler();
void set_interrupt_phase(InterruptPhase phase);
// Whether the render in progress should stop: a signal came, or the live view asked for a new render.
bool interrupt_requested();
// Whether a signal came (SIGINT or SIGTERM): the run should end.
bool signal_received();
// The live view: stop the render in progress as a signal would (true), or let the next one run (false).
void set_render_restart(bool restart);
bool render_restart_requested();
// 128 + the signal's number, as a shell reports a process ended by it: 130 for SIGINT, 143 for SIGTERM.
int interrupted_exit_status();
// For tests: as if the user had pressed Ctrl-C (or, with false, as if not).
void set_interrupt_requested(bool requested);

}  // namespace rt
