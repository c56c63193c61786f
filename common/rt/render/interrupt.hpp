// Signals during a run, chosen as git chooses for its lock and temporary files: no staging file
// (staged_file.hpp) survives a signal that ends the process.
// - SIGINT (Ctrl-C), SIGTERM, SIGHUP (the terminal closed) and SIGXCPU (a CPU-time limit, as batch systems
//   set) stop the run: the first asks the render loop to stop after the sample each thread is on (so the
//   image so far can be saved, marked partial), or, once the render is over, lets the files being written
//   be finished; a second one, of any of these, removes every staging file and exits at once, writing
//   nothing.
// - SIGQUIT (Ctrl-\), SIGUSR1, SIGUSR2 and SIGALRM, which end a process at once by default, still do, but
//   remove the staging files first.
// - SIGPIPE and SIGXFSZ are ignored, as curl ignores SIGPIPE: a closed pipe costs the messages, not the
//   files, and a file larger than the limit is a write that fails with its reason.
// Each exits with 128 + the signal's number, as a shell reports a process ended by it.
// The live view (live_view.hpp) also stops a render this way, without a signal, to render again with
// other knobs.
#pragma once

namespace rt {

// What a first signal interrupts, for the message it prints. kReading: a tool (rt_merge, rt_compare) has
// written nothing yet, and will not.
enum class InterruptPhase { kReading, kRendering, kWriting, kLive };

// Installs the handler for the signals above.
void install_interrupt_handler();
void set_interrupt_phase(InterruptPhase phase);
// Whether the render in progress should stop: a signal came, or the live view asked for a new render.
bool interrupt_requested();
// Whether a signal that stops the run came: it should end.
bool signal_received();
// The live view: stop the render in progress as a signal would (true), or let the next one run (false).
void set_render_restart(bool restart);
bool render_restart_requested();
// 128 + the signal's number: 130 for SIGINT, 143 for SIGTERM, 129 for SIGHUP.
int interrupted_exit_status();
// Before a program writes its files: true, having said "PROGRAM: interrupted; nothing written", when a signal
// came (the program then exits with interrupted_exit_status()); otherwise enters the writing phase.
bool stop_before_writing(const char* program);
// Once it has written them: its exit status, 0, or after a signal that came while it wrote, having said
// "PROGRAM: interrupted while writing; WHAT was written all the same", interrupted_exit_status().
int status_after_writing(const char* program, const char* what);
// For tests: as if the user had pressed Ctrl-C (or, with false, as if not).
void set_interrupt_requested(bool requested);

}  // namespace rt
