// The progress of a render on stderr: a bar with the elapsed and remaining time when stderr is a terminal, a
// plain line at every 10 % otherwise, nothing when quiet. The render loop shows it, and so does any renderer
// that takes its samples elsewhere (chapter 11's GPU passes).
#pragma once

#include "rt/render/render_loop.hpp"

namespace rt {

class Progress {
  public:
    // kAuto becomes a bar on a terminal and lines otherwise.
    explicit Progress(ProgressStyle style);

    // `fraction` of the work is done after `elapsed` seconds.
    void show(double fraction, double elapsed);
    // Removes the bar (nothing to do for lines).
    void clear();
    bool animated() const { return style_ == ProgressStyle::kBar; }

  private:
    ProgressStyle style_;
    int last_decile_ = 0;
};

}  // namespace rt
