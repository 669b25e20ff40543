#include "bvh_import.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/runner/message_text.h"

namespace pba::lab {

namespace an = pba::animation;

namespace {

constexpr size_t kMaxJoints = 10'000;             // far beyond any capture rig
constexpr long kMaxFrames = 10'000'000;           // frames of one clip
constexpr std::uintmax_t kMaxBytes = 512u << 20;  // [bytes] as the graphics import

/// Whitespace-separated words with the line each came from.
class Words {
 public:
  explicit Words(std::istream& in) : in_(in) {}
  /// The next word, or empty at the end of the file.
  std::string next() {
    while (pos_ >= words_.size()) {
      std::string text;
      if (!std::getline(in_, text)) return {};
      ++line_;
      std::istringstream split(text);
      words_.clear();
      pos_ = 0;
      for (std::string w; split >> w;) words_.push_back(w);
    }
    return words_[pos_++];
  }
  int line() const { return line_; }

 private:
  std::istream& in_;
  std::vector<std::string> words_;
  size_t pos_ = 0;
  int line_ = 0;
};

bool number(const std::string& word, Real& out) {
  if (word.empty()) return false;
  char* end = nullptr;
  out = std::strtod(word.c_str(), &end);
  return end == word.c_str() + word.size() && std::isfinite(out);
}

struct Joint {
  int parent = -1;
  std::vector<int> channels;  // 0–2 position x, y, z; 3–5 rotation about x, y, z
  int first = 0;              // index of its first channel in a frame
};

}  // namespace

bool isBvhPath(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".bvh";
}

Result<BvhClip> readBvh(const std::string& path) {
  const std::string shown = app::oneLine(path);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return Error{shown + ": is a directory"};
  if (!std::filesystem::is_regular_file(path, ec)) return Error{shown + ": is not a regular file"};
  if (const auto size = std::filesystem::file_size(path, ec); !ec && size > kMaxBytes)
    return Error{shown + ": larger than " + std::to_string(kMaxBytes) + " bytes"};
  std::ifstream in(path);
  if (!in) return Error{shown + ": cannot open"};
  Words words(in);
  auto fail = [&](const std::string& what) {
    return Error{shown + ": line " + std::to_string(words.line()) + ": " + what};
  };
  BvhClip out;
  std::vector<Joint> joints;
  int channelCount = 0;
  if (words.next() != "HIERARCHY") return fail("expected HIERARCHY");
  std::vector<int> open;  // joints whose '}' is still to come (-2: an End Site)
  std::string word = words.next();
  if (word != "ROOT") return fail("expected ROOT");
  while (true) {
    // word is ROOT, JOINT or End (Site): a name, '{', OFFSET x y z, CHANNELS n ... for joints.
    const bool end = word == "End";
    std::string name = words.next();
    if (end) {
      if (name != "Site") return fail("expected 'End Site'");
      if (open.empty() || open.back() < 0) return fail("an End Site outside a joint");
      name = "EndSite_" + out.skeleton.names[static_cast<size_t>(open.back())];
    } else if (name.empty() || name == "{") {
      return fail("expected the joint's name");
    }
    if (words.next() != "{") return fail("expected '{'");
    if (words.next() != "OFFSET") return fail("expected OFFSET");
    Vec3 offset(0.0);
    for (int k = 0; k < 3; ++k)
      if (!number(words.next(), offset[k])) return fail("expected OFFSET and 3 numbers");
    if (out.skeleton.find(name) >= 0) return fail("joint name '" + name + "' is used twice (names must be unique)");
    if (joints.size() >= kMaxJoints) return fail("more than " + std::to_string(kMaxJoints) + " joints");
    Joint j;
    j.parent = open.empty() ? -1 : open.back();
    if (!open.empty() && open.back() < 0) return fail("a joint inside an End Site");
    j.first = channelCount;
    if (!end) {
      if (words.next() != "CHANNELS") return fail("expected CHANNELS");
      Real n = 0.0;
      if (!number(words.next(), n) || n < 0 || n > 6 || n != std::floor(n)) return fail("expected CHANNELS 0 to 6");
      for (int c = 0; c < static_cast<int>(n); ++c) {
        const std::string ch = words.next();
        static const char* kNames[] = {"Xposition", "Yposition", "Zposition", "Xrotation", "Yrotation", "Zrotation"};
        const auto it = std::find(std::begin(kNames), std::end(kNames), ch);
        if (it == std::end(kNames)) return fail("unknown channel '" + ch + "'");
        j.channels.push_back(static_cast<int>(it - std::begin(kNames)));
      }
      channelCount += static_cast<int>(j.channels.size());
    }
    out.skeleton.add(name, j.parent, offset);
    joints.push_back(j);
    open.push_back(end ? -2 : static_cast<int>(joints.size()) - 1);
    // Close braces, then the next joint or MOTION.
    while (true) {
      word = words.next();
      if (word == "}") {
        if (open.empty()) return fail("unbalanced '}'");
        open.pop_back();
        continue;
      }
      break;
    }
    if (word == "MOTION") {
      if (!open.empty()) return fail("MOTION before every joint is closed");
      break;
    }
    if (word != "JOINT" && word != "End")
      return fail(word.empty() ? "unexpected end of file" : "unexpected '" + word + "'");
  }
  // MOTION: Frames: N, Frame Time: T, then N lines of channelCount numbers.
  Real frames = 0.0, frameTime = 0.0;
  if (words.next() != "Frames:" || !number(words.next(), frames) || frames < 0 || frames > kMaxFrames ||
      frames != std::floor(frames))
    return fail("expected 'Frames: N'");
  if (words.next() != "Frame" || words.next() != "Time:" || !number(words.next(), frameTime) || !(frameTime > 0.0))
    return fail("expected 'Frame Time: T' with T > 0");
  an::Clip& clip = out.clip;
  clip.tracks.resize(joints.size());
  clip.frames = static_cast<int>(frames);
  clip.duration = (frames - 1.0) * frameTime;
  std::vector<Real> values(static_cast<size_t>(channelCount));
  for (int f = 0; f < clip.frames; ++f) {
    for (Real& v : values)
      if (!number(words.next(), v))
        return fail("frame " + std::to_string(f) + ": expected " + std::to_string(channelCount) + " numbers");
    const Real t = f * frameTime;
    for (size_t i = 0; i < joints.size(); ++i) {
      const Joint& j = joints[i];
      if (j.channels.empty()) continue;
      Vec3 position = out.skeleton.restTranslations[i];
      bool moved = false;
      Quat q(1, 0, 0, 0);
      bool turned = false;
      for (size_t c = 0; c < j.channels.size(); ++c) {
        const Real v = values[static_cast<size_t>(j.first) + c];
        const int kind = j.channels[c];
        if (kind < 3) {
          if (!moved) position = Vec3(0.0);  // position channels replace the OFFSET
          position[kind] = v;
          moved = true;
        } else {
          Vec3 axis(0.0);
          axis[kind - 3] = 1.0;
          q = q * glm::angleAxis(v * kPi / 180.0, axis);
          turned = true;
        }
      }
      an::JointTrack& track = clip.tracks[i];
      if (moved) static_cast<void>(track.translation.insert(t, position));
      if (turned) static_cast<void>(track.rotation.insert(t, glm::normalize(q)));
    }
  }
  return out;
}

}  // namespace pba::lab
