#include "evaluation/svg_frames.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "missions/svg.hpp"
#include "simulator/epuck.hpp"

namespace sd {

SvgFrameWriter::SvgFrameWriter(const Mission& mission, std::filesystem::path folder, int every)
    : background_(mission_svg(mission)), folder_(std::move(folder)), every_(std::max(1, every)), last_tick_(mission.ticks) {
  background_.erase(background_.rfind("</svg>"));
  const std::size_t at = background_.find("viewBox=\"");
  double width = 1;
  if (at == std::string::npos ||
      // NOLINTNEXTLINE(cert-err34-c): our own drawing's viewBox; a bad one fails the count of 4
      std::sscanf(background_.c_str() + at + 9, "%lf %lf %lf %lf", &view_x_, &view_y_, &width, &view_height_) != 4)
    throw std::logic_error("a mission drawing without a viewBox");
  std::filesystem::create_directories(folder_);
}

void SvgFrameWriter::on_tick(const Simulation& sim) {
  const int tick = sim.tick();
  if (tick % every_ != 0 && tick != last_tick_) return;
  const SwarmState& s = sim.swarm();
  const double r = epuck::kBodyRadius;
  std::ostringstream out;
  out << background_ << "<g class=\"robots\" transform=\"scale(1 -1)\">\n";
  char colour[8];
  for (int i = 0; i < s.size; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec2 p = s.position[k];
    std::snprintf(colour, sizeof colour, "#%06x", s.led[k] & 0xffffffu);
    out << "<circle cx=\"" << p.x << "\" cy=\"" << p.y << "\" r=\"" << r << "\" fill=\"" << (s.led[k] ? colour : "#9aa3ad")
        << "\" stroke=\"#1d2430\" stroke-width=\"" << r * 0.12 << "\"/>"
        << "<line x1=\"" << p.x << "\" y1=\"" << p.y << "\" x2=\"" << p.x + std::cos(s.yaw[k]) * r << "\" y2=\""
        << p.y + std::sin(s.yaw[k]) * r << "\" stroke=\"#1d2430\" stroke-width=\"" << r * 0.2 << "\"/>\n";
  }
  out << "</g>\n";
  // Written at 1000x and scaled down, as the drawing's captions: renderers hint tiny fonts badly.
  const double line = view_height_ / 30;
  char text[160];
  std::snprintf(text, sizeof text, "tick %d / %d &#183; %.1f s &#183; objective %.6g", tick, last_tick_, tick * epuck::kTickSeconds, sim.score());
  // A pale band behind it, so that it reads over the arena (about 0.55 em per character; the
  // two &#183; entities are one character each).
  out << "<rect class=\"overlay-band\" x=\"" << view_x_ << "\" y=\"" << view_y_ << "\" width=\""
      << line * (1.0 + 0.8 * 0.55 * static_cast<double>(std::strlen(text) - 10)) << "\" height=\"" << line * 1.6
      << "\" fill=\"#ffffff\" fill-opacity=\"0.8\"/>\n";
  out << "<text class=\"overlay\" transform=\"translate(" << view_x_ + line * 0.5 << " " << view_y_ + line * 1.2
      << ") scale(0.001)\" font-family=\"sans-serif\" font-size=\"" << line * 800 << "\" fill=\"#1d2430\">" << text << "</text>\n</svg>\n";
  char name[32];
  std::snprintf(name, sizeof name, "frame-%05d.svg", tick);
  std::ofstream file(folder_ / name);
  if (!(file << out.str())) throw std::runtime_error("cannot write " + (folder_ / name).string());
  ++frames_;
}

}  // namespace sd
