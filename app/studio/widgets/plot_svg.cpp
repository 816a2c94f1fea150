// Plots as SVG: the plot's own drawing (plot.cpp) on a canvas that writes SVG elements, so the
// picture is the one on screen, with text as text.

#include <cstdio>
#include <vector>

#include "widgets/plot.hpp"
#include "widgets/plot_canvas.hpp"

namespace pagor::studio {
namespace {

std::string escaped(const char* text) {
  std::string out;
  for (const char* c = text; *c; ++c) {
    switch (*c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += *c;
    }
  }
  return out;
}

// An ImGui colour (ABGR) as SVG attributes `name="rgb(...)" name-opacity="a"`.
std::string color(const char* name, ImU32 c) {
  char buf[96];
  std::snprintf(buf, sizeof(buf), "%s=\"rgb(%u,%u,%u)\" %s-opacity=\"%.3f\"", name, c & 0xFF,
                (c >> 8) & 0xFF, (c >> 16) & 0xFF, name, ((c >> 24) & 0xFF) / 255.0);
  return buf;
}

std::string num(float v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.2f", v);
  return buf;
}

class SvgCanvas : public PlotCanvas {
 public:
  void AddLine(const ImVec2& a, const ImVec2& b, ImU32 col, float thickness) override {
    add("<line x1=\"" + num(a.x) + "\" y1=\"" + num(a.y) + "\" x2=\"" + num(b.x) + "\" y2=\"" +
        num(b.y) + "\" " + color("stroke", col) + " stroke-width=\"" + num(thickness) + "\"/>");
  }
  void AddRect(const ImVec2& a, const ImVec2& b, ImU32 col) override {
    add(rect(a, b) + " fill=\"none\" " + color("stroke", col) + "/>");
  }
  void AddRectFilled(const ImVec2& a, const ImVec2& b, ImU32 col) override {
    add(rect(a, b) + " " + color("fill", col) + "/>");
  }
  void AddCircle(const ImVec2& c, float r, ImU32 col, int, float thickness) override {
    add(circle(c, r) + " fill=\"none\" " + color("stroke", col) + " stroke-width=\"" +
        num(thickness) + "\"/>");
  }
  void AddCircleFilled(const ImVec2& c, float r, ImU32 col) override {
    add(circle(c, r) + " " + color("fill", col) + "/>");
  }
  void AddPolyline(const ImVec2* p, int n, ImU32 col, int, float thickness) override {
    std::string points;
    for (int i = 0; i < n; ++i) points += num(p[i].x) + "," + num(p[i].y) + " ";
    add("<polyline points=\"" + points + "\" fill=\"none\" " + color("stroke", col) +
        " stroke-width=\"" + num(thickness) + "\"/>");
  }
  void AddText(ImFont*, float size, const ImVec2& at, ImU32 col, const char* text) override {
    // ImGui places text by its top; SVG by its baseline (DejaVu's ascent is ~0.93 of the size).
    add("<text x=\"" + num(at.x) + "\" y=\"" + num(at.y + size * 0.93f) + "\" font-size=\"" +
        num(size) + "\" " + color("fill", col) + ">" + escaped(text) + "</text>");
  }
  void PushClipRect(const ImVec2& a, const ImVec2& b, bool) override {
    const std::string id = "clip" + std::to_string(++clips_);
    defs_ += "<clipPath id=\"" + id + "\">" + rect(a, b) + "/></clipPath>\n";
    add("<g clip-path=\"url(#" + id + ")\">");
    ++depth_;
  }
  void PopClipRect() override {
    if (depth_ > 0) --depth_, add("</g>");
  }

  std::string document(int w, int h) const {
    std::string body = body_;
    for (int i = 0; i < depth_; ++i) body += "</g>\n";
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
           "width=\"" +
           std::to_string(w) + "\" height=\"" + std::to_string(h) + "\" viewBox=\"0 0 " +
           std::to_string(w) + " " + std::to_string(h) +
           "\" font-family=\"DejaVu Sans, sans-serif\">\n<defs>\n" + defs_ + "</defs>\n" + body +
           "</svg>\n";
  }

 private:
  static std::string rect(const ImVec2& a, const ImVec2& b) {
    return "<rect x=\"" + num(a.x) + "\" y=\"" + num(a.y) + "\" width=\"" + num(b.x - a.x) +
           "\" height=\"" + num(b.y - a.y) + "\"";
  }
  static std::string circle(const ImVec2& c, float r) {
    return "<circle cx=\"" + num(c.x) + "\" cy=\"" + num(c.y) + "\" r=\"" + num(r) + "\"";
  }
  void add(const std::string& element) { body_ += element + "\n"; }

  std::string body_, defs_;
  int clips_ = 0, depth_ = 0;
};

}  // namespace

std::string plot_svg(const Plot& plot, int width, int height, float font_size) {
  SvgCanvas canvas;
  draw_plot(&canvas, ImVec2(0, 0), ImVec2(float(width), float(height)), plot, font_size);
  return canvas.document(width, height);
}

}  // namespace pagor::studio
