#include "fapcast/codec/bvh_text.hpp"

#include "fapcast/core/input_error.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <set>
#include <stdexcept>

namespace fapcast {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

bool keyword_is(std::string_view token, std::string_view keyword) {
  if (token.size() != keyword.size()) return false;
  for (std::size_t i = 0; i < token.size(); ++i) {
    const auto a = static_cast<unsigned char>(token[i]);
    const auto b = static_cast<unsigned char>(keyword[i]);
    if (std::tolower(a) != std::tolower(b)) return false;
  }
  return true;
}

// Walks the file line by line (LF, CRLF or lone CR), skipping blank lines, and turns every
// failure into an InputError at the current line.
class LineReader {
 public:
  LineReader(std::string_view bytes, std::string_view source) : bytes_(bytes), source_(source) {}

  // The next non-blank line's tokens; false at the end of the input.
  bool next(std::vector<std::string_view>& tokens) {
    while (pos_ < bytes_.size()) {
      ++line_;
      std::size_t end = pos_;
      while (end < bytes_.size() && bytes_[end] != '\n' &&
             !(bytes_[end] == '\r' && (end + 1 == bytes_.size() || bytes_[end + 1] != '\n')))
        ++end;
      const std::string_view text = bytes_.substr(pos_, end - pos_);
      pos_ = end + 1;
      tokens.clear();
      std::size_t i = 0;
      while (i < text.size()) {
        while (i < text.size() && is_space(text[i])) ++i;
        const std::size_t start = i;
        while (i < text.size() && !is_space(text[i])) ++i;
        if (i > start) tokens.push_back(text.substr(start, i - start));
      }
      if (!tokens.empty()) return true;
    }
    return false;
  }

  // The next non-blank line, which must exist: `rule` names what was expected.
  const std::vector<std::string_view>& expect(std::string_view rule, std::string_view what) {
    if (!next(tokens_)) fail(rule, "file ends where " + std::string(what) + " was expected");
    return tokens_;
  }

  [[noreturn]] void fail(std::string_view rule, const std::string& detail) const {
    throw InputError({std::string(source_), line_ == 0 ? 1 : line_, std::nullopt},
                     std::string(rule), detail);
  }

  std::vector<std::string_view> tokens_;

 private:
  std::string_view bytes_;
  std::string_view source_;
  std::size_t pos_ = 0;
  std::uint64_t line_ = 0;
};

// A finite decimal number, optionally signed: "1", "-0.5", "+2e-3".
std::optional<double> parse_number(std::string_view token) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token.front() == '-') return std::nullopt;  // "+-1"
  }
  double v = 0.0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
  if (ec != std::errc{} || end != token.data() + token.size() || !std::isfinite(v))
    return std::nullopt;
  return v;
}

std::string quoted(std::string_view token) { return "'" + std::string(token) + "'"; }

Eigen::Vector3d read_offset(LineReader& in) {
  const auto& t = in.expect("offset", "OFFSET x y z");
  if (!keyword_is(t[0], "OFFSET")) in.fail("offset", "expected OFFSET x y z, got " + quoted(t[0]));
  if (t.size() != 4)
    in.fail("offset", "OFFSET takes 3 numbers, got " + std::to_string(t.size() - 1));
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) {
    const auto n = parse_number(t[static_cast<std::size_t>(i) + 1]);
    if (!n) in.fail("number", "OFFSET value " + quoted(t[static_cast<std::size_t>(i) + 1]) +
                                  " is not a finite number");
    v[i] = *n;
  }
  return v;
}

void expect_open_brace(LineReader& in) {
  const auto& t = in.expect("expected-open-brace", "'{'");
  if (t.size() != 1 || t[0] != "{") in.fail("expected-open-brace", "expected '{', got " + quoted(t[0]));
}

std::vector<BvhChannel> read_channels(LineReader& in) {
  const auto& t = in.expect("channels", "CHANNELS n ...");
  if (!keyword_is(t[0], "CHANNELS"))
    in.fail("channels", "expected CHANNELS n ..., got " + quoted(t[0]));
  if (t.size() < 2) in.fail("channels", "CHANNELS without a count");
  std::uint32_t n = 0;
  const auto [end, ec] = std::from_chars(t[1].data(), t[1].data() + t[1].size(), n);
  if (ec != std::errc{} || end != t[1].data() + t[1].size() || n > 6)
    in.fail("channels", "channel count " + quoted(t[1]) + " is not a whole number 0..6");
  if (t.size() - 2 != n)
    in.fail("channels", "CHANNELS says " + std::to_string(n) + " but names " +
                            std::to_string(t.size() - 2));
  std::vector<BvhChannel> channels;
  for (std::size_t i = 2; i < t.size(); ++i) {
    const auto c = parse_bvh_channel(t[i]);
    if (!c) in.fail("channels", "unknown channel " + quoted(t[i]));
    for (BvhChannel seen : channels)
      if (seen == *c) in.fail("channels", "channel " + quoted(t[i]) + " appears twice");
    channels.push_back(*c);
  }
  return channels;
}

// The joint name: the rest of the line, words joined by '_' as Blender does.
std::string joint_name(LineReader& in, const std::vector<std::string_view>& t) {
  if (t.size() < 2) in.fail("joint-name", quoted(t[0]) + " without a name");
  std::string name(t[1]);
  for (std::size_t i = 2; i < t.size(); ++i) name += "_" + std::string(t[i]);
  return name;
}

void read_hierarchy(LineReader& in, BvhDocument& doc) {
  const auto& first = in.expect("missing-hierarchy", "HIERARCHY");
  if (first.size() != 1 || !keyword_is(first[0], "HIERARCHY"))
    in.fail("missing-hierarchy", "a BVH file starts with HIERARCHY, got " + quoted(first[0]));
  const auto& root = in.expect("missing-root", "ROOT name");
  if (!keyword_is(root[0], "ROOT"))
    in.fail("missing-root", "expected ROOT name, got " + quoted(root[0]));

  std::set<std::string, std::less<>> names;
  std::vector<int> open;  // the joints whose '{' is not closed yet, root first
  auto begin_joint = [&](const std::vector<std::string_view>& t, int parent) {
    if (doc.joints.size() >= kBvhMaxJoints)
      in.fail("too-many-joints", "more than " + std::to_string(kBvhMaxJoints) + " joints");
    if (open.size() >= kBvhMaxDepth)
      in.fail("too-deep", "joints nested deeper than " + std::to_string(kBvhMaxDepth));
    BvhJoint joint;
    joint.name = joint_name(in, t);
    joint.parent = parent;
    if (!names.insert(joint.name).second)
      in.fail("duplicate-joint-name", "joint name " + quoted(joint.name) + " is used twice");
    expect_open_brace(in);
    joint.offset = read_offset(in);
    joint.channels = read_channels(in);
    doc.joints.push_back(std::move(joint));
    open.push_back(static_cast<int>(doc.joints.size() - 1));
  };
  begin_joint(std::vector<std::string_view>(root), -1);

  std::vector<bool> has_children(1, false);
  while (!open.empty()) {
    const auto& t = in.expect(
        "unclosed-joint",
        "'}' closing joint " + quoted(doc.joints[static_cast<std::size_t>(open.back())].name));
    BvhJoint& current = doc.joints[static_cast<std::size_t>(open.back())];
    if (keyword_is(t[0], "JOINT")) {
      if (current.end_site)
        in.fail("end-site-mixed", "joint " + quoted(current.name) + " has an End Site and joints");
      has_children[static_cast<std::size_t>(open.back())] = true;
      const int parent = open.back();
      begin_joint(std::vector<std::string_view>(t), parent);
      has_children.push_back(false);
    } else if (keyword_is(t[0], "End") && t.size() >= 2 && keyword_is(t[1], "Site")) {
      if (current.end_site || has_children[static_cast<std::size_t>(open.back())])
        in.fail("end-site-mixed",
                "joint " + quoted(current.name) + " has a second End Site or joints and one");
      expect_open_brace(in);
      current.end_site = read_offset(in);
      const auto& close = in.expect("unclosed-end-site", "'}' closing End Site");
      if (close.size() != 1 || close[0] != "}")
        in.fail("unclosed-end-site", "expected '}' after the End Site OFFSET, got " + quoted(close[0]));
    } else if (t.size() == 1 && t[0] == "}") {
      open.pop_back();
    } else if (keyword_is(t[0], "ROOT")) {
      in.fail("multiple-roots", "a second ROOT inside joint " + quoted(current.name));
    } else {
      in.fail("unexpected-keyword", "expected JOINT, End Site or '}', got " + quoted(t[0]));
    }
  }
}

void read_motion(LineReader& in, BvhDocument& doc) {
  const auto& m = in.expect("missing-motion", "MOTION");
  if (keyword_is(m[0], "ROOT")) in.fail("multiple-roots", "fapcast reads one ROOT per file");
  if (m.size() != 1 || !keyword_is(m[0], "MOTION"))
    in.fail("missing-motion", "expected MOTION after the hierarchy, got " + quoted(m[0]));
  const std::size_t width = doc.channel_count();
  if (width == 0) in.fail("no-channels", "the hierarchy has no channels to animate");

  const auto& f = in.expect("frames", "Frames: N");
  std::uint64_t declared = 0;
  if (f.size() != 2 || !keyword_is(f[0], "Frames:"))
    in.fail("frames", "expected 'Frames: N', got " + quoted(f[0]));
  const auto [fend, fec] = std::from_chars(f[1].data(), f[1].data() + f[1].size(), declared);
  if (fec != std::errc{} || fend != f[1].data() + f[1].size())
    in.fail("frames", "frame count " + quoted(f[1]) + " is not a whole number");
  doc.frame_count = declared;

  const auto& ft = in.expect("frame-time", "Frame Time: seconds");
  if (ft.size() != 3 || !keyword_is(ft[0], "Frame") || !keyword_is(ft[1], "Time:"))
    in.fail("frame-time", "expected 'Frame Time: seconds', got " + quoted(ft[0]));
  const auto dt = parse_number(ft[2]);
  if (!dt || !(*dt > 0.0))
    in.fail("frame-time", "frame time " + quoted(ft[2]) + " is not a positive number");
  doc.frame_time_s = *dt;

  std::uint64_t rows = 0;
  std::vector<std::string_view> t;
  while (in.next(t)) {
    if (rows == declared)
      in.fail("frame-count-mismatch",
              "more motion lines than 'Frames: " + std::to_string(declared) + "'");
    if (t.size() != width)
      in.fail("motion-value-count", "motion line has " + std::to_string(t.size()) +
                                        " values, the hierarchy has " + std::to_string(width) +
                                        " channels");
    for (std::string_view token : t) {
      const auto v = parse_number(token);
      if (!v) in.fail("number", "motion value " + quoted(token) + " is not a finite number");
      doc.motion.push_back(*v);
    }
    ++rows;
  }
  if (rows != declared)
    in.fail("frame-count-mismatch", "'Frames: " + std::to_string(declared) + "' but " +
                                        std::to_string(rows) + " motion lines");
}

// Shortest fixed notation that reads back to the same double.
void append_number(std::string& out, double v) {
  std::array<char, 400> buf;
  const auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), v,
                                       std::chars_format::fixed);
  if (ec != std::errc{}) throw std::invalid_argument("BVH: number does not fit in fixed notation");
  out.append(buf.data(), end);
}

void append_vector(std::string& out, const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) {
    out += ' ';
    append_number(out, v[i]);
  }
}

void check_writable(const BvhDocument& doc) {
  if (doc.joints.empty()) throw std::invalid_argument("BVH: no joints");
  if (!(doc.frame_time_s > 0.0) || !std::isfinite(doc.frame_time_s))
    throw std::invalid_argument("BVH: frame time must be positive");
  std::set<std::string_view> names;
  for (const BvhJoint& j : doc.joints) {
    if (j.name.empty() || j.name.find_first_of(" \t\r\n\v\f") != std::string::npos)
      throw std::invalid_argument("BVH: joint name '" + j.name + "' is empty or has whitespace");
    if (!names.insert(j.name).second)
      throw std::invalid_argument("BVH: joint name '" + j.name + "' is used twice");
  }
  if (doc.motion.size() != doc.frame_count * doc.channel_count())
    throw std::invalid_argument("BVH: motion holds " + std::to_string(doc.motion.size()) +
                                " values, not frame_count * channel_count()");
  for (double v : doc.motion)
    if (!std::isfinite(v)) throw std::invalid_argument("BVH: a motion value is not finite");
}

}  // namespace

BvhDocument read_bvh(std::string_view bytes, std::string_view source) {
  LineReader in(bytes, source);
  BvhDocument doc;
  read_hierarchy(in, doc);
  read_motion(in, doc);
  return doc;
}

std::string write_bvh(const BvhDocument& doc) {
  check_writable(doc);
  std::string out = "HIERARCHY\n";
  std::vector<std::size_t> open;
  auto indent = [&](std::size_t depth) { out.append(depth, '\t'); };
  auto close = [&] {
    const BvhJoint& j = doc.joints[open.back()];
    const std::size_t depth = open.size() - 1;
    if (j.end_site) {
      indent(depth + 1), out += "End Site\n";
      indent(depth + 1), out += "{\n";
      indent(depth + 2), out += "OFFSET", append_vector(out, *j.end_site), out += '\n';
      indent(depth + 1), out += "}\n";
    }
    indent(depth), out += "}\n";
    open.pop_back();
  };
  for (std::size_t i = 0; i < doc.joints.size(); ++i) {
    const BvhJoint& j = doc.joints[i];
    while (!open.empty() && static_cast<int>(open.back()) != j.parent) close();
    if ((i == 0) != (j.parent < 0) || (i > 0 && open.empty()))
      throw std::invalid_argument("BVH: joint '" + j.name +
                                  "' is not in depth-first order under one root");
    if (!open.empty() && doc.joints[open.back()].end_site)
      throw std::invalid_argument("BVH: joint '" + doc.joints[open.back()].name +
                                  "' has both an End Site and joints");
    const std::size_t depth = open.size();
    indent(depth), out += (i == 0 ? "ROOT " : "JOINT "), out += j.name, out += '\n';
    indent(depth), out += "{\n";
    indent(depth + 1), out += "OFFSET", append_vector(out, j.offset), out += '\n';
    indent(depth + 1), out += "CHANNELS " + std::to_string(j.channels.size());
    for (BvhChannel c : j.channels) out += ' ', out += to_string(c);
    out += '\n';
    open.push_back(i);
  }
  while (!open.empty()) close();

  out += "MOTION\nFrames: " + std::to_string(doc.frame_count) + "\nFrame Time: ";
  append_number(out, doc.frame_time_s);
  out += '\n';
  const std::size_t width = doc.channel_count();
  for (std::uint64_t k = 0; k < doc.frame_count; ++k) {
    for (std::size_t c = 0; c < width; ++c) {
      if (c > 0) out += ' ';
      append_number(out, doc.motion[k * width + c]);
    }
    out += '\n';
  }
  return out;
}

}  // namespace fapcast
