#pragma once
// evaluate --render DIR: a run as a sequence of SVG frames (frame-00000.svg, ...), each the
// mission's drawing with the robots (LED colour, heading) and the tick, time and objective
// written on it, for slides and supplementary material (ffmpeg or any SVG tool makes a video).
#include <filesystem>
#include <string>

#include "evaluation/simulation.hpp"

namespace sd {

class SvgFrameWriter : public TickObserver {
 public:
  /// Every `every` ticks (and the last one); creates `folder` if needed.
  SvgFrameWriter(const Mission& mission, std::filesystem::path folder, int every);
  void on_tick(const Simulation& simulation) override;
  int frames_written() const { return frames_; }

 private:
  std::string background_;  // the mission's drawing, without its closing tag
  std::filesystem::path folder_;
  int every_;
  int last_tick_;
  int frames_ = 0;
  double view_x_ = 0, view_y_ = 0, view_height_ = 1;  // the drawing's viewBox
};

}  // namespace sd
