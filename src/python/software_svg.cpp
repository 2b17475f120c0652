#include "python/software_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "control/describe.hpp"
#include "core/markup_text.hpp"

namespace sd::python {

namespace {

constexpr double kBoxHeight = 40.0;
constexpr double kCharWidth = 6.6;  // 11 px sans-serif, roughly

struct Point {
  double x = 0.0, y = 0.0;
};

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", v);
  return text;
}

double box_width(const std::string& label) { return std::max(60.0, static_cast<double>(label.size()) * kCharWidth + 16.0); }

std::string box(Point centre, const std::string& label, bool double_border, const char* fill) {
  const double w = box_width(label), h = kBoxHeight;
  std::string out = "<rect x=\"" + number(centre.x - w / 2) + "\" y=\"" + number(centre.y - h / 2) + "\" width=\"" +
                    number(w) + "\" height=\"" + number(h) + "\" rx=\"8\" fill=\"" + fill + "\" stroke=\"#333\"/>\n";
  if (double_border)
    out += "<rect x=\"" + number(centre.x - w / 2 - 4) + "\" y=\"" + number(centre.y - h / 2 - 4) + "\" width=\"" +
           number(w + 8) + "\" height=\"" + number(h + 8) + "\" rx=\"11\" fill=\"none\" stroke=\"#333\"/>\n";
  out += "<text x=\"" + number(centre.x) + "\" y=\"" + number(centre.y + 4) + "\" text-anchor=\"middle\">" +
         markup_text(label) + "</text>\n";
  return out;
}

std::string document(double width, double height, const std::string& body) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(width) + "\" height=\"" + number(height) +
         "\" viewBox=\"0 0 " + number(width) + " " + number(height) +
         "\" font-family=\"sans-serif\" font-size=\"11\">\n"
         "<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"10\" refY=\"5\" markerWidth=\"8\" markerHeight=\"8\" "
         "orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"#333\"/></marker></defs>\n"
         "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n" +
         body + "</svg>\n";
}

std::string fsm_svg(const Fsm& fsm) {
  const std::size_t n = fsm.states.size();
  std::vector<std::string> labels(n);
  double widest = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    labels[i] = std::to_string(i) + ": " + describe_module(fsm.states[i].behaviour, ModuleKind::Behaviour);
    widest = std::max(widest, box_width(labels[i]));
  }
  const double radius = n > 1 ? std::max(120.0, widest * 0.75) : 0.0;
  const double margin = widest / 2 + 160.0;
  const Point centre{radius + margin, radius + 90.0};
  std::vector<Point> at(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = -std::numbers::pi / 2 + 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    at[i] = {centre.x + radius * std::cos(angle), centre.y + radius * std::sin(angle)};
  }
  std::string edges, boxes;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& transitions = fsm.states[i].transitions;
    for (std::size_t t = 0; t < transitions.size(); ++t) {
      const auto target = static_cast<std::size_t>(transitions[t].target);
      if (target >= n) continue;
      const std::string label = describe_module(transitions[t].condition, ModuleKind::Condition);
      const Point a = at[i], b = at[target];
      const double dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy);
      if (length < 1e-9) continue;
      // Two states joined both ways get two arcs, one each side; parallel edges bend further.
      const double bend = 30.0 + 22.0 * static_cast<double>(t);
      const Point normal{-dy / length, dx / length};
      const Point control{(a.x + b.x) / 2 + normal.x * bend, (a.y + b.y) / 2 + normal.y * bend};
      // Start and end at the boxes' edges (roughly: where the curve leaves a box's height).
      const double shorten = kBoxHeight / 2 + 6.0;
      const auto toward = [&](Point from, Point to) {
        const double ux = to.x - from.x, uy = to.y - from.y, l = std::hypot(ux, uy);
        return Point{from.x + ux / l * shorten, from.y + uy / l * shorten};
      };
      const Point start = toward(a, control), end = toward(b, control);
      edges += "<path d=\"M" + number(start.x) + "," + number(start.y) + " Q" + number(control.x) + "," +
               number(control.y) + " " + number(end.x) + "," + number(end.y) +
               "\" fill=\"none\" stroke=\"#333\" marker-end=\"url(#arrow)\"/>\n";
      const Point middle{(start.x + 2 * control.x + end.x) / 4, (start.y + 2 * control.y + end.y) / 4};
      edges += "<text x=\"" + number(middle.x + normal.x * 8) + "\" y=\"" + number(middle.y + normal.y * 8 + 4) +
               "\" text-anchor=\"middle\" fill=\"#1a4f8a\">" + markup_text(label) + "</text>\n";
    }
  }
  for (std::size_t i = 0; i < n; ++i) boxes += box(at[i], labels[i], i == 0, "#fff7d6");
  return document(2 * centre.x, 2 * centre.y, edges + boxes);
}

std::string node_text(const BtNode& node) {
  switch (node.type) {
    case BtNodeType::Selector: return "Selector (?)";
    case BtNodeType::SelectorStar: return "Selector* (?*)";
    case BtNodeType::Sequence: return "Sequence (->)";
    case BtNodeType::SequenceStar: return "Sequence* (->*)";
    case BtNodeType::Negation: return "Not";
    case BtNodeType::Action: {
      std::string label = describe_module(node.module, ModuleKind::Behaviour);
      if (node.success_probability > 0.0) label += " p=" + number(node.success_probability);
      return label;
    }
    case BtNodeType::Condition: return describe_module(node.module, ModuleKind::Condition) + "?";
  }
  return "?";
}

std::string tree_svg(const BehaviourTree& tree) {
  const std::size_t n = tree.nodes.size();
  if (n == 0) return document(200, 60, "<text x=\"10\" y=\"30\">empty tree</text>\n");
  std::vector<std::string> labels(n);
  double column = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    labels[i] = node_text(tree.nodes[i]);
    column = std::max(column, box_width(labels[i]) + 16.0);
  }
  std::vector<Point> at(n);
  std::vector<bool> placed(n, false);
  double next_leaf = 0.0;
  int depth_max = 0;
  // Leaves left to right in depth-first order; a parent centred over its children.
  const auto place = [&](const auto& self, std::size_t node, int depth) -> void {
    if (placed[node]) return;  // a malformed tree cannot loop the layout
    placed[node] = true;
    depth_max = std::max(depth_max, depth);
    const auto& children = tree.nodes[node].children;
    double sum = 0.0;
    int count = 0;
    for (const int child : children) {
      if (child < 0 || static_cast<std::size_t>(child) >= n || placed[static_cast<std::size_t>(child)]) continue;
      self(self, static_cast<std::size_t>(child), depth + 1);
      sum += at[static_cast<std::size_t>(child)].x;
      ++count;
    }
    const double x = count > 0 ? sum / count : (next_leaf++ + 0.5) * column;
    at[node] = {x, 40.0 + 80.0 * depth};
  };
  place(place, 0, 0);
  std::string edges, boxes;
  for (std::size_t i = 0; i < n; ++i) {
    if (!placed[i]) continue;
    for (const int child : tree.nodes[i].children) {
      if (child < 0 || static_cast<std::size_t>(child) >= n) continue;
      const Point a = at[i], b = at[static_cast<std::size_t>(child)];
      edges += "<line x1=\"" + number(a.x) + "\" y1=\"" + number(a.y + kBoxHeight / 2) + "\" x2=\"" + number(b.x) +
               "\" y2=\"" + number(b.y - kBoxHeight / 2) + "\" stroke=\"#333\"/>\n";
    }
    const BtNodeType type = tree.nodes[i].type;
    const char* fill = type == BtNodeType::Action ? "#fff7d6" : type == BtNodeType::Condition ? "#e3f0ff" : "#eeeeee";
    boxes += box(at[i], labels[i], false, fill);
  }
  return document(std::max(column, next_leaf * column), 80.0 * (depth_max + 1), edges + boxes);
}

}  // namespace

std::string software_svg(const ControlSoftware& software) {
  switch (software.architecture) {
    case Architecture::Fsm: return fsm_svg(software.fsm);
    case Architecture::BehaviourTree: return tree_svg(software.bt);
    case Architecture::NeuralNetwork: break;
  }
  return document(360, 80, box({180, 40}, "EvoStick network: 25 inputs -> 2 wheels", false, "#fff7d6"));
}

}  // namespace sd::python
