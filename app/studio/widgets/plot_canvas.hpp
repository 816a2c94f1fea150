#pragma once
/// \file plot_canvas.hpp
/// What a plot is drawn on: ImGui's draw list (the screen and PNG exports) or an SVG document
/// (plot_svg). The methods are named and typed as ImDrawList's, so the plot's drawing code reads
/// the same whichever it draws on.

#include <imgui.h>

#include <string>

namespace pagor::studio {

class PlotCanvas {
 public:
  virtual ~PlotCanvas() = default;
  virtual void AddLine(const ImVec2& a, const ImVec2& b, ImU32 col, float thickness = 1.0f) = 0;
  virtual void AddRect(const ImVec2& a, const ImVec2& b, ImU32 col) = 0;
  virtual void AddRectFilled(const ImVec2& a, const ImVec2& b, ImU32 col) = 0;
  virtual void AddCircle(const ImVec2& c, float radius, ImU32 col, int segments = 0,
                         float thickness = 1.0f) = 0;
  virtual void AddCircleFilled(const ImVec2& c, float radius, ImU32 col) = 0;
  virtual void AddPolyline(const ImVec2* points, int count, ImU32 col, int flags,
                           float thickness) = 0;
  virtual void AddText(ImFont* font, float size, const ImVec2& at, ImU32 col, const char* text) = 0;
  virtual void PushClipRect(const ImVec2& a, const ImVec2& b, bool intersect = false) = 0;
  virtual void PopClipRect() = 0;
};

/// A canvas that draws into an ImGui draw list.
class DrawListCanvas : public PlotCanvas {
 public:
  explicit DrawListCanvas(ImDrawList* list) : d_(list) {}
  void AddLine(const ImVec2& a, const ImVec2& b, ImU32 col, float thickness) override {
    d_->AddLine(a, b, col, thickness);
  }
  void AddRect(const ImVec2& a, const ImVec2& b, ImU32 col) override { d_->AddRect(a, b, col); }
  void AddRectFilled(const ImVec2& a, const ImVec2& b, ImU32 col) override {
    d_->AddRectFilled(a, b, col);
  }
  void AddCircle(const ImVec2& c, float r, ImU32 col, int segments, float thickness) override {
    d_->AddCircle(c, r, col, segments, thickness);
  }
  void AddCircleFilled(const ImVec2& c, float r, ImU32 col) override {
    d_->AddCircleFilled(c, r, col);
  }
  void AddPolyline(const ImVec2* p, int n, ImU32 col, int flags, float thickness) override {
    d_->AddPolyline(p, n, col, flags, thickness);
  }
  void AddText(ImFont* font, float size, const ImVec2& at, ImU32 col, const char* text) override {
    d_->AddText(font, size, at, col, text);
  }
  void PushClipRect(const ImVec2& a, const ImVec2& b, bool intersect) override {
    d_->PushClipRect(a, b, intersect);
  }
  void PopClipRect() override { d_->PopClipRect(); }

 private:
  ImDrawList* d_;
};

}  // namespace pagor::studio
