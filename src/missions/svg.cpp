#include "missions/svg.hpp"

#include "core/markup_text.hpp"
#include "missions/svg_layers.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace sd {

namespace {

constexpr const char* kOutsideColor = "#eef1f5";  // svg.hpp: no floor is this colour

std::string rgb_text(std::uint32_t rgb) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%06x", rgb & 0xffffffu);
  return buffer;
}

std::string region_element(const Region& r, const std::string& style) {
  std::ostringstream out;
  switch (r.shape) {
    case Region::Shape::Circle:
      out << "<circle cx=\"" << r.center.x << "\" cy=\"" << r.center.y << "\" r=\"" << r.radius << "\" " << style << "/>";
      break;
    case Region::Shape::Rectangle:
      out << "<rect x=\"" << -r.half_size.x << "\" y=\"" << -r.half_size.y << "\" width=\"" << 2 * r.half_size.x
          << "\" height=\"" << 2 * r.half_size.y << "\" transform=\"translate(" << r.center.x << " " << r.center.y
          << ") rotate(" << r.yaw * 180.0 / kPi << ")\" " << style << "/>";
      break;
    case Region::Shape::Polygon:
      out << "<polygon points=\"";
      for (const Vec2 v : r.vertices) out << v.x << "," << v.y << " ";
      out << "\" " << style << "/>";
      break;
  }
  return out.str();
}

/// The colour each wall shows once the mission's fixed events have run (LED blocks take their
/// LEDs' colour; 0 = none). Random choices cannot be drawn: describe_random_events says them.
std::vector<std::uint32_t> wall_colors(const Mission& m) {
  std::vector<std::uint32_t> color(m.arena.walls.size());
  for (std::size_t w = 0; w < color.size(); ++w) color[w] = m.arena.walls[w].led_color;
  for (const ArenaLed& led : m.arena.leds)
    if (led.initial_color) color[led.wall] = led.initial_color;
  for (const MissionEvent& e : m.events) {
    if (e.first_tick != e.last_tick) continue;
    for (const MissionEvent::LedChange& c : e.leds) {
      if (c.side == MissionEvent::kRandom || c.block == MissionEvent::kRandom) continue;
      for (const LedArena::Block& b : m.led_arena.blocks)
        if ((c.side == MissionEvent::kEvery || c.side == b.side) && (c.block == MissionEvent::kEvery || c.block == b.block))
          color[b.wall] = c.color;
    }
  }
  return color;
}

std::vector<std::string> describe_random_events(const Mission& m) {
  auto selector = [](const char* what, int s) {
    return s == MissionEvent::kRandom ? std::string("a random ") + what
                                      : s == MissionEvent::kEvery ? std::string("every ") + what : std::string(what) + " " + std::to_string(s);
  };
  std::vector<std::string> lines;
  for (const MissionEvent& e : m.events) {
    bool random = e.first_tick != e.last_tick;
    for (const MissionEvent::LedChange& c : e.leds) random = random || c.side == MissionEvent::kRandom || c.block == MissionEvent::kRandom;
    if (!random) continue;
    std::string line = "Event '" + e.name + "' at tick " + std::to_string(e.first_tick);
    if (e.last_tick != e.first_tick) line += " to " + std::to_string(e.last_tick) + " (random)";
    for (const MissionEvent::LedChange& c : e.leds)
      line += ": " + selector("block", c.block) + " of " + selector("side", c.side) + " turns " + rgb_text(c.color);
    lines.push_back(line);
  }
  return lines;
}

constexpr std::size_t kCaptionChars = 44;  // per caption line, so that it fits the drawing's width

/// Text broken at spaces into lines of at most `width` characters (a longer word keeps its line).
std::vector<std::string> wrapped(const std::string& text, std::size_t width) {
  std::vector<std::string> lines;
  std::istringstream words(text);
  std::string line;
  for (std::string word; words >> word;) {
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      lines.push_back(line);
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

}  // namespace

std::string mission_svg(const Mission& m) {
  // Bounds: the arena's walls (the floor beyond them is not drawn), start region, jail and
  // lit lights, with a small margin; without walls, the floor patches and at least 1 m square.
  const std::vector<Vec2> outline = arena_outline(m);
  Vec2 lo{1e9, 1e9}, hi{-1e9, -1e9};
  auto grow = [&](Vec2 a, Vec2 b) {
    lo = {std::min(lo.x, a.x), std::min(lo.y, a.y)};
    hi = {std::max(hi.x, b.x), std::max(hi.y, b.y)};
  };
  for (const Vec2 p : outline) grow(p, p);
  if (outline.empty()) {
    grow({-0.5, -0.5}, {0.5, 0.5});
    for (const FloorPatch& p : m.arena.floor_patches) grow(p.region.bounds().first, p.region.bounds().second);
  }
  grow(m.start.bounds().first, m.start.bounds().second);
  if (m.arrest) grow(m.arrest->jail.bounds().first, m.arrest->jail.bounds().second);
  for (const Light& l : m.arena.lights)  // an unlit light is not drawn: it must not widen the picture
    if (l.intensity > 0) grow(l.position.xy(), l.position.xy());
  const double margin = 0.04 * std::max(hi.x - lo.x, hi.y - lo.y);
  lo = lo - Vec2{margin, margin};
  hi = hi + Vec2{margin, margin};

  std::vector<std::string> captions;
  for (const std::string& event : describe_random_events(m))
    for (std::string& l : wrapped(event, kCaptionChars)) captions.push_back(std::move(l));
  const double line = (hi.x - lo.x) / 18;  // caption line height: readable at any arena size
  std::ostringstream out;
  const double width = hi.x - lo.x, height = hi.y - lo.y + line * static_cast<double>(captions.size());
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << static_cast<int>(width * 250) << "\" height=\""
      << static_cast<int>(height * 250) << "\" viewBox=\"" << lo.x << " " << -hi.y << " " << width << " " << height
      << "\">\n";
  out << "<title>" << markup_text(m.title) << " (" << markup_text(m.name) << ")</title>\n";
  // Outside the arena: a neutral colour that no floor has.
  out << "<rect class=\"outside\" x=\"" << lo.x << "\" y=\"" << -hi.y << "\" width=\"" << width << "\" height=\"" << height
      << "\" fill=\"" << kOutsideColor << "\"/>\n";
  // The world's y axis points up; SVG's points down.
  out << "<g transform=\"scale(1 -1)\">\n";
  if (!outline.empty()) {
    out << "<clipPath id=\"arena\"><polygon points=\"";
    for (const Vec2 p : outline) out << p.x << "," << p.y << " ";
    out << "\"/></clipPath>\n";
  }
  out << "<g class=\"floor\"" << (outline.empty() ? "" : " clip-path=\"url(#arena)\"") << ">\n";
  out << "<rect x=\"" << lo.x << "\" y=\"" << lo.y << "\" width=\"" << width << "\" height=\"" << hi.y - lo.y
      << "\" fill=\"" << rgb_text(m.arena.floor_background_rgb) << "\"/>\n";
  // Patches are drawn last-first so that the first matching patch ends on top, as it wins.
  for (auto it = m.arena.floor_patches.rbegin(); it != m.arena.floor_patches.rend(); ++it)
    out << region_element(it->region, "class=\"patch\" fill=\"" + rgb_text(it->rgb) + "\"") << "\n";
  out << objective_layer(m, lo, hi) << "\n";
  out << "</g>\n";
  out << region_element(m.start, "class=\"start\" fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"0.012\" stroke-dasharray=\"0.04 0.03\"")
      << "\n";
  if (m.arrest)  // where the Coconut arrest rule sends robots that leave
    out << region_element(m.arrest->jail, "class=\"jail\" fill=\"#c0392b\" fill-opacity=\"0.25\" stroke=\"#c0392b\" stroke-width=\"0.012\" stroke-dasharray=\"0.04 0.03\"")
        << "\n";
  const std::vector<std::uint32_t> colors = wall_colors(m);
  for (std::size_t k = 0; k < m.arena.walls.size(); ++k) {
    const Wall& w = m.arena.walls[k];
    const double angle = w.axis.angle() * 180.0 / kPi;
    // Lit LED blocks are drawn thicker, with a dark outline, so that their colours show.
    const double thickness = std::max(2 * w.half_thickness, colors[k] ? 0.03 : 0.012);
    out << "<rect class=\"wall\" x=\"" << -w.half_length << "\" y=\"" << -0.5 * thickness << "\" width=\"" << 2 * w.half_length
        << "\" height=\"" << thickness << "\" transform=\"translate(" << w.center.x << " " << w.center.y << ") rotate(" << angle
        << ")\" fill=\"" << (colors[k] ? rgb_text(colors[k]) : "#303030") << "\""
        << (m.led_arena.empty() ? "" : " stroke=\"#202020\" stroke-width=\"0.004\"") << "/>\n";
  }
  for (const Light& l : m.arena.lights) {
    if (l.intensity <= 0) continue;
    out << "<circle class=\"light\" cx=\"" << l.position.x << "\" cy=\"" << l.position.y << "\" r=\"0.05\" fill=\"" << rgb_text(l.rgb)
        << "\" stroke=\"#806000\" stroke-width=\"0.01\"/>\n";
  }
  out << "</g>\n";
  for (std::size_t i = 0; i < captions.size(); ++i)
    // Text drawn at 1000x and scaled down: renderers hint tiny font sizes badly.
    out << "<text class=\"caption\" transform=\"translate(" << lo.x + 0.3 * line << " " << -lo.y + line * (static_cast<double>(i) + 0.75)
        << ") scale(0.001)\" font-family=\"sans-serif\" font-size=\"" << line * 650 << "\">" << markup_text(captions[i]) << "</text>\n";
  out << "</svg>\n";
  return out.str();
}

}  // namespace sd
