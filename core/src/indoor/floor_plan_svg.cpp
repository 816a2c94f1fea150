// The SVG floor-plan reader: a small tag scanner (no external XML library), enough for the flat
// drawings CAD tools export. Every failure names the file, the element (tag, number, line).

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <vector>

#include "pagor/errors.hpp"
#include "pagor/indoor/floor_plan.hpp"
#include "io/parse_numbers.hpp"

namespace pagor {
namespace {

struct Tag {
  std::string name;
  std::map<std::string, std::string> attributes;
  int line = 1;
  int number = 0;             ///< 1-based count of this tag name in the file
  bool closing = false;       ///< an end tag, </name>
  bool self_closing = false;  ///< <name ... />: no content, no end tag
  std::size_t end = 0;        ///< offset just after the tag's '>'
};

struct Scanner {
  std::string_view text;
  std::string origin;
  std::size_t pos = 0;

  mutable std::size_t counted = 0;  // lines are counted once, up to `counted`
  mutable int counted_lines = 1;
  int line_at(std::size_t offset) const {
    if (offset < counted) {  // only for an error behind the scan position
      counted = 0;
      counted_lines = 1;
    }
    for (; counted < offset && counted < text.size(); ++counted)
      counted_lines += text[counted] == '\n';
    return counted_lines;
  }
  [[noreturn]] void fail(std::size_t offset, const std::string& what) const {
    throw InputError(origin + ":" + std::to_string(line_at(offset)) + ": " + what);
  }
  // Skips to after `end`; false at the end of the text.
  bool skip_past(std::string_view end) {
    const std::size_t e = text.find(end, pos);
    if (e == std::string_view::npos) return false;
    pos = e + end.size();
    return true;
  }
  // The next start tag, or false at the end. End tags, comments, declarations are skipped.
  bool next(Tag& tag) {
    for (;;) {
      const std::size_t lt = text.find('<', pos);
      if (lt == std::string_view::npos) return false;
      pos = lt + 1;
      const std::string_view rest = text.substr(pos);
      if (rest.substr(0, 3) == "!--") {
        if (!skip_past("-->")) fail(lt, "unterminated comment");
        continue;
      }
      if (rest.substr(0, 1) == "?" || rest.substr(0, 1) == "!") {
        if (!skip_past(">")) fail(lt, "unterminated markup");
        continue;
      }
      if (rest.substr(0, 1) == "/") {  // an end tag: its name, for the nesting
        tag = Tag{};
        tag.closing = true;
        for (++pos; pos < text.size() && text[pos] != '>' &&
                    !std::isspace(static_cast<unsigned char>(text[pos]));)
          tag.name += text[pos++];
        if (!skip_past(">")) fail(lt, "unterminated markup");
        tag.end = pos;
        return true;
      }
      read_tag(lt, tag);
      return true;
    }
  }
  void read_tag(std::size_t lt, Tag& tag) {
    tag = Tag{};
    tag.line = line_at(lt);
    const auto name_char = [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == ':' || c == '-' || c == '_' ||
             c == '.';
    };
    while (pos < text.size() && name_char(text[pos])) tag.name += text[pos++];
    if (tag.name.empty()) fail(lt, "a '<' that starts no element");
    for (;;) {
      while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
      if (pos >= text.size()) fail(lt, "<" + tag.name + "> is not closed");
      if (text[pos] == '>' || text[pos] == '/') {
        tag.self_closing = text[pos] == '/';
        if (!skip_past(">")) fail(lt, "<" + tag.name + "> is not closed");
        tag.end = pos;
        return;
      }
      std::string key;
      while (pos < text.size() && name_char(text[pos])) key += text[pos++];
      if (key.empty() || pos >= text.size() || text[pos] != '=')
        fail(lt, "<" + tag.name + ">: malformed attribute near '" +
                     parse::printable(text.substr(pos, 20)) + "'");
      ++pos;
      if (pos >= text.size() || (text[pos] != '"' && text[pos] != '\''))
        fail(lt, "<" + tag.name + "> attribute " + key + ": value must be quoted");
      const char quote = text[pos++];
      const std::size_t end = text.find(quote, pos);
      if (end == std::string_view::npos)
        fail(lt, "<" + tag.name + "> attribute " + key + ": unterminated value");
      tag.attributes[key] = std::string(text.substr(pos, end - pos));
      pos = end + 1;
    }
  }
};

struct Context {
  std::string origin;
  double scale = 0;  ///< metres per SVG unit
  [[noreturn]] void fail(const Tag& t, const std::string& what) const {
    throw InputError(origin + ":" + std::to_string(t.line) + ": <" + t.name + "> #" +
                     std::to_string(t.number) + ": " + what);
  }
  double number(const Tag& t, const std::string& key, std::optional<double> fallback = {}) const {
    const auto it = t.attributes.find(key);
    if (it == t.attributes.end()) {
      if (fallback) return *fallback;
      fail(t, "missing attribute " + key);
    }
    std::string_view v = it->second;
    if (v.size() > 2 && v.substr(v.size() - 2) == "px") v.remove_suffix(2);
    const auto d = parse::to_double(v);
    if (!d || !std::isfinite(*d))
      fail(t, "attribute " + key + "=\"" + parse::printable(it->second) + "\" is not a number");
    return *d;
  }
  Eigen::Vector2d metric(double x, double y) const { return {x * scale, -y * scale}; }
};

// Numbers in a points list or path data: separated by whitespace and/or commas.
std::vector<std::string_view> tokens(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  const auto sep = [](char c) { return std::isspace(static_cast<unsigned char>(c)) || c == ','; };
  while (i < s.size()) {
    while (i < s.size() && sep(s[i])) ++i;
    if (i >= s.size()) break;
    std::size_t b = i;
    if (std::isalpha(static_cast<unsigned char>(s[i])) && s[i] != 'e' && s[i] != 'E') {
      out.push_back(s.substr(i++, 1));  // a path command letter
      continue;
    }
    ++i;
    while (i < s.size() && !sep(s[i]) &&
           !(std::isalpha(static_cast<unsigned char>(s[i])) && s[i] != 'e' && s[i] != 'E') &&
           !((s[i] == '-' || s[i] == '+') && s[i - 1] != 'e' && s[i - 1] != 'E'))
      ++i;
    out.push_back(s.substr(b, i - b));
  }
  return out;
}

PlanWall polyline_of(const Context& ctx, const Tag& t, bool closed) {
  const auto it = t.attributes.find("points");
  if (it == t.attributes.end()) ctx.fail(t, "missing attribute points");
  const auto tok = tokens(it->second);
  if (tok.size() % 2 != 0) ctx.fail(t, "points: an odd count of coordinates");
  PlanWall w;
  w.closed = closed;
  for (std::size_t i = 0; i < tok.size(); i += 2) {
    const auto x = parse::to_double(tok[i]), y = parse::to_double(tok[i + 1]);
    if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y))
      ctx.fail(t, "points: coordinate pair " + std::to_string(i / 2 + 1) + " is not a number");
    w.points.push_back(ctx.metric(*x, *y));
  }
  if (w.points.size() < 2) ctx.fail(t, "points: a wall needs at least two points");
  return w;
}

void path_walls(const Context& ctx, const Tag& t, std::vector<PlanWall>& out) {
  const auto it = t.attributes.find("d");
  if (it == t.attributes.end()) ctx.fail(t, "missing attribute d");
  const auto tok = tokens(it->second);
  Eigen::Vector2d cur(0, 0), start(0, 0);  // SVG units
  PlanWall w;
  const auto flush = [&] {
    if (w.points.size() >= 2) out.push_back(w);
    w = PlanWall{};
  };
  char cmd = 0;
  std::size_t i = 0;
  const auto num = [&](const char* what) {
    if (i >= tok.size()) ctx.fail(t, std::string("d: command ") + cmd + " lacks its " + what);
    const auto v = parse::to_double(tok[i]);
    if (!v || !std::isfinite(*v))
      ctx.fail(t, "d: '" + parse::printable(tok[i]) + "' is not a number");
    ++i;
    return *v;
  };
  while (i < tok.size()) {
    if (std::isalpha(static_cast<unsigned char>(tok[i][0]))) cmd = tok[i++][0];
    const bool rel = std::islower(static_cast<unsigned char>(cmd));
    // A line-to right after Z starts a new subpath at the closed one's start.
    if (cmd != 0 && std::toupper(static_cast<unsigned char>(cmd)) != 'M' && w.points.empty())
      w.points.push_back(ctx.metric(cur.x(), cur.y()));
    switch (std::toupper(static_cast<unsigned char>(cmd))) {
      case 'M': {
        flush();
        const double x = num("x"), y = num("y");
        cur = rel ? cur + Eigen::Vector2d(x, y) : Eigen::Vector2d(x, y);
        start = cur;
        w.points.push_back(ctx.metric(cur.x(), cur.y()));
        cmd = rel ? 'l' : 'L';  // further pairs are line-tos
        break;
      }
      case 'L': {
        const double x = num("x"), y = num("y");
        cur = rel ? cur + Eigen::Vector2d(x, y) : Eigen::Vector2d(x, y);
        w.points.push_back(ctx.metric(cur.x(), cur.y()));
        break;
      }
      case 'H':
        cur.x() = rel ? cur.x() + num("x") : num("x");
        w.points.push_back(ctx.metric(cur.x(), cur.y()));
        break;
      case 'V':
        cur.y() = rel ? cur.y() + num("y") : num("y");
        w.points.push_back(ctx.metric(cur.x(), cur.y()));
        break;
      case 'Z':
        w.closed = true;
        cur = start;
        flush();
        cmd = 0;
        break;
      case 0:
        ctx.fail(t, "d: path data must start with a command (M)");
      default:
        ctx.fail(t, std::string("d: command '") + cmd +
                        "' (a curve or arc) is not supported; flatten curves to lines on export");
    }
  }
  flush();
}

// Metres per SVG unit that make sense for a plan: a micrometre to ten kilometres.
constexpr double kMinScale = 1e-6, kMaxScale = 1e4;

double checked_scale(const Context& ctx, const Tag& svg, double s, const std::string& from) {
  if (!(s >= kMinScale && s <= kMaxScale))
    ctx.fail(svg,
             from + " gives " + std::to_string(s) + " metres per SVG unit, outside [1e-06, 10000]");
  return s;
}

double svg_scale(const Context& ctx, const Tag& svg) {
  if (svg.attributes.count("data-scale"))
    return checked_scale(ctx, svg, ctx.number(svg, "data-scale"), "data-scale");
  const auto w = svg.attributes.find("width");
  const auto vb = svg.attributes.find("viewBox");
  if (w != svg.attributes.end() && vb != svg.attributes.end()) {
    const std::string& ws = w->second;
    double unit = 0;
    std::string_view num(ws);
    for (const auto& [suffix, metres] :
         {std::pair<const char*, double>{"mm", 1e-3}, {"cm", 1e-2}, {"m", 1.0}}) {
      const std::string_view sfx(suffix);
      if (num.size() > sfx.size() && num.substr(num.size() - sfx.size()) == sfx) {
        unit = metres;
        num.remove_suffix(sfx.size());
        break;
      }
    }
    const auto width = parse::to_double(num);
    const auto box = tokens(vb->second);
    const auto box_w = box.size() == 4 ? parse::to_double(box[2]) : std::nullopt;
    if (unit > 0 && width && box_w && *width > 0 && *box_w > 0)
      return checked_scale(ctx, svg, *width * unit / *box_w, "width / viewBox width");
  }
  ctx.fail(svg,
           "no scale: add data-scale=\"S\" (metres per SVG unit) to <svg>, or give width in m, "
           "cm or mm with a viewBox");
}

// Containers whose content is not drawn where it stands (definitions, clip paths, masks, ...).
bool hides_content(const std::string& name) {
  return name == "defs" || name == "symbol" || name == "clipPath" || name == "mask" ||
         name == "pattern" || name == "marker";
}

// Anything that would move or scale drawn geometry is refused rather than ignored: a plan read
// without its transform would be silently off.
void reject_placement(const Context& ctx, const Tag& t, bool root) {
  if (t.attributes.count("transform"))
    ctx.fail(t, "transform attributes are not supported; apply transforms on export");
  if (const auto style = t.attributes.find("style");
      style != t.attributes.end() && style->second.find("transform") != std::string::npos)
    ctx.fail(t, "a CSS transform in style is not supported; apply transforms on export");
  if (t.name == "svg" && !root)
    ctx.fail(t,
             "nested <svg> elements are not supported (their x, y and viewBox place their "
             "content); flatten the drawing on export");
  if (t.name == "use")
    ctx.fail(t,
             "<use> is not supported (it places copies of other elements); expand it on "
             "export");
}

bool is_shape(const std::string& name) {
  return name == "line" || name == "polyline" || name == "polygon" || name == "rect" ||
         name == "path" || name == "circle" || name == "ellipse";
}

void add_shape(const Context& ctx, const Tag& t, FloorPlan& plan) {
  const std::size_t walls_before = plan.walls.size(), columns_before = plan.columns.size();
  if (t.name == "line") {
    PlanWall w;
    w.points = {ctx.metric(ctx.number(t, "x1"), ctx.number(t, "y1")),
                ctx.metric(ctx.number(t, "x2"), ctx.number(t, "y2"))};
    plan.walls.push_back(w);
  } else if (t.name == "polyline" || t.name == "polygon") {
    plan.walls.push_back(polyline_of(ctx, t, t.name == "polygon"));
  } else if (t.name == "rect") {
    const double x = ctx.number(t, "x", 0.0), y = ctx.number(t, "y", 0.0);
    const double w = ctx.number(t, "width"), h = ctx.number(t, "height");
    if (!(w > 0) || !(h > 0)) ctx.fail(t, "width and height must be > 0");
    plan.walls.push_back(
        {{ctx.metric(x, y), ctx.metric(x + w, y), ctx.metric(x + w, y + h), ctx.metric(x, y + h)},
         true});
  } else if (t.name == "path") {
    path_walls(ctx, t, plan.walls);
  } else {
    const double r = t.name == "circle" ? ctx.number(t, "r") : ctx.number(t, "rx");
    if (t.name == "ellipse" && std::abs(ctx.number(t, "ry") - r) > 1e-9 * std::abs(r))
      ctx.fail(t, "an ellipse with rx != ry is not a circular column");
    const double radius = r * ctx.scale;
    if (!(radius > 0) || radius > kMaxColumnRadius)
      ctx.fail(t, "radius " + std::to_string(radius) + " m is outside (0, 100] m");
    plan.columns.push_back(
        {ctx.metric(ctx.number(t, "cx", 0.0), ctx.number(t, "cy", 0.0)), radius});
  }
  for (std::size_t w = walls_before; w < plan.walls.size(); ++w)
    for (const Eigen::Vector2d& p : plan.walls[w].points)
      if (!(p.cwiseAbs().maxCoeff() <= kMaxPlanCoordinate))
        ctx.fail(t, "a point lies more than 1e7 m from the origin");
  for (std::size_t c = columns_before; c < plan.columns.size(); ++c)
    if (!(plan.columns[c].center.cwiseAbs().maxCoeff() <= kMaxPlanCoordinate))
      ctx.fail(t, "the centre lies more than 1e7 m from the origin");
}

}  // namespace

FloorPlan parse_floor_plan_svg(std::string_view text, const std::string& origin) {
  Scanner sc{text, origin};
  Context ctx{origin};
  FloorPlan plan;
  std::map<std::string, int> counts;
  std::vector<std::string> open;  // the elements the scan is inside, outermost first
  int hidden = 0;                 // how many of them hide their content
  Tag t;
  bool seen_svg = false;
  while (sc.next(t)) {
    if (t.closing) {  // close up to the matching start tag (lenient about unclosed ones)
      const auto it = std::find(open.rbegin(), open.rend(), t.name);
      if (it != open.rend())
        for (std::size_t n = static_cast<std::size_t>(it - open.rbegin()) + 1; n > 0; --n) {
          hidden -= hides_content(open.back());
          open.pop_back();
        }
      continue;
    }
    t.number = ++counts[t.name];
    reject_placement(ctx, t, !seen_svg);
    if (t.name == "style" && !t.self_closing) {  // a style sheet: refuse CSS transforms
      const std::size_t end = text.find("</style", t.end);
      if (text.substr(t.end, end - t.end).find("transform") != std::string_view::npos)
        ctx.fail(t,
                 "a CSS transform in a style sheet is not supported; apply transforms on "
                 "export");
    }
    if (!t.self_closing) {
      open.push_back(t.name);
      hidden += hides_content(t.name);
    }
    if (t.name == "svg" && !seen_svg) {
      ctx.scale = svg_scale(ctx, t);
      seen_svg = true;
      continue;
    }
    if (!is_shape(t.name) || hidden > 0) continue;
    if (!seen_svg) ctx.fail(t, "appears before the <svg> element");
    add_shape(ctx, t, plan);
  }
  if (!seen_svg) throw InputError(origin + ": not an SVG file (no <svg> element)");
  if (plan.walls.empty() && plan.columns.empty())
    throw InputError(origin + ": the plan has neither walls nor columns");
  return plan;
}

}  // namespace pagor
