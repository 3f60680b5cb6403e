#include "sim/trial_svg.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace oasis::hw::sim {
namespace {

constexpr double kWidth = 900.0;
constexpr double kMargin = 50.0;
constexpr double kTimelineTop = 40.0;
constexpr double kTimelineHeight = 200.0;
constexpr double kMapTop = 300.0;
constexpr double kMapHeight = 260.0;
constexpr const char* kColour[] = {"#d62728", "#c9a400"};  // human 1 red, human 2 yellow
constexpr const char* kRobotColour = "#1f3b73";

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  return text;
}

// Text as SVG character data: the markup characters escaped.
std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

struct Box {  // data (x0..x1, y0..y1) -> pixels (left..left+width, bottom..bottom-height)
  double x0, x1, y0, y1, left, top, width, height;
  double px(double x) const { return left + (x - x0) / (x1 - x0) * width; }
  double py(double y) const { return top + height - (y - y0) / (y1 - y0) * height; }
};

std::string polyline(const std::vector<std::pair<double, double>>& points, const Box& box,
                     const std::string& style) {
  std::string text = "<polyline fill=\"none\" " + style + " points=\"";
  for (const auto& [x, y] : points)
    text += number(box.px(x)) + "," + number(box.py(y)) + " ";
  return text + "\"/>\n";
}

std::string label(double x, double y, const std::string& text, const std::string& extra = "") {
  return "<text x=\"" + number(x) + "\" y=\"" + number(y) + "\" " + extra + ">" + text +
         "</text>\n";
}

// Holder h (1 or 2) drawn at the height of its belief axis: human 1 at 1, human 2 at 0.
double holder_level(int holder) {
  return holder == 1 ? 1.0 : 0.0;
}

std::string timeline(const std::vector<TraceStep>& trace) {
  const double end = std::max(trace.back().time_s, 1e-9);
  const Box box{
      0.0, end, -0.05, 1.05, kMargin, kTimelineTop, kWidth - 2 * kMargin, kTimelineHeight};
  std::vector<std::pair<double, double>> truth, inferred, belief;
  std::string rewards;
  for (const TraceStep& step : trace) {
    truth.emplace_back(step.time_s, holder_level(step.true_holder));
    inferred.emplace_back(step.time_s, holder_level(step.inferred_holder));
    belief.emplace_back(step.time_s, step.belief_human1);
    if (step.rewarded)
      rewards += "<rect x=\"" + number(box.px(step.time_s)) + "\" y=\"" +
                 number(kTimelineTop + kTimelineHeight + 4) + "\" width=\"" +
                 number(box.width / static_cast<double>(trace.size()) + 0.5) +
                 "\" height=\"6\" fill=\"#2ca02c\"/>\n";
  }
  std::string svg = "<rect x=\"" + number(box.left) + "\" y=\"" + number(box.top) + "\" width=\"" +
                    number(box.width) + "\" height=\"" + number(box.height) +
                    "\" fill=\"none\" stroke=\"#999\"/>\n";
  svg += polyline(belief, box, "stroke=\"#7f7f7f\" stroke-width=\"1\"");
  svg += polyline(truth, box, "stroke=\"#000\" stroke-width=\"3\" opacity=\"0.35\"");
  svg +=
      polyline(inferred, box, "stroke=\"#1f77b4\" stroke-width=\"1.5\" stroke-dasharray=\"4 2\"");
  svg += rewards;
  svg += label(box.left - 45, box.py(1.0) + 4, "human 1", "font-size=\"11\"");
  svg += label(box.left - 45, box.py(0.0) + 4, "human 2", "font-size=\"11\"");
  svg += label(box.left, box.top + box.height + 26,
               "time 0 to " + number(end) +
                   " s. thick grey: true holder; dashed blue: inferred; thin grey: belief that "
                   "human 1 holds the treat; green: true reward 1",
               "font-size=\"11\"");
  return svg;
}

std::string map(const std::vector<TraceStep>& trace, double hallway_width_m) {
  double x0 = 0.0, x1 = 1.0, y0 = -hallway_width_m / 2.0, y1 = hallway_width_m / 2.0;
  for (const TraceStep& step : trace) {
    for (const go1::PlanarPoint& p :
         {go1::PlanarPoint{step.robot.x, step.robot.y}, step.people[0], step.people[1]}) {
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
      y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
  }
  // Equal scales in x and y, so the hallway looks like one.
  const double scale = std::min((kWidth - 2 * kMargin) / (x1 - x0), (kMapHeight - 20) / (y1 - y0));
  const Box box{x0, x1, y0, y1, kMargin, kMapTop, (x1 - x0) * scale, (y1 - y0) * scale};
  std::string svg;
  for (double wall : {-hallway_width_m / 2.0, hallway_width_m / 2.0})
    svg += "<line x1=\"" + number(box.px(x0)) + "\" x2=\"" + number(box.px(x1)) + "\" y1=\"" +
           number(box.py(wall)) + "\" y2=\"" + number(box.py(wall)) +
           "\" stroke=\"#bbb\" stroke-width=\"2\"/>\n";
  std::vector<std::pair<double, double>> robot, people[2];
  for (const TraceStep& step : trace) {
    robot.emplace_back(step.robot.x, step.robot.y);
    for (std::size_t i = 0; i < 2; ++i)
      people[i].emplace_back(step.people[i].x, step.people[i].y);
  }
  for (std::size_t i = 0; i < 2; ++i)
    svg +=
        polyline(people[i], box, std::string("stroke=\"") + kColour[i] + "\" stroke-width=\"1.5\"");
  svg += polyline(robot, box, std::string("stroke=\"") + kRobotColour + "\" stroke-width=\"2.5\"");
  svg += label(box.left, box.top - 8,
               "paths, odometry frame (1 m = " + number(scale) +
                   " px): robot blue, human 1 red, human 2 yellow; start at the left",
               "font-size=\"11\"");
  return svg;
}

}  // namespace

std::string trial_svg(const std::vector<TraceStep>& trace, const std::string& title,
                      double hallway_width_m) {
  const double height = kMapTop + kMapHeight + 20;
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(kWidth) +
                    "\" height=\"" + number(height) + "\" font-family=\"sans-serif\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg += label(kMargin, 24, escaped(title), "font-size=\"14\"");
  if (!trace.empty()) svg += timeline(trace) + map(trace, hallway_width_m);
  return svg + "</svg>\n";
}

void write_file_atomically(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw std::runtime_error("cannot rename " + temporary.string() + " to " + path.string());
  }
}

}  // namespace oasis::hw::sim
