#include "sfm_pruning/io/openmvg_features.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <string_view>

#include "sfm_pruning/io/colmap_binary.hpp"
#include "sfm_pruning/io/openmvg_text_tokens.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;

namespace {

// Column layouts of a .feat line (see the header).
constexpr size_t kPointColumns = 2;
constexpr size_t kScaleOrientationColumns = 4;
constexpr size_t kAffineColumns = 8;

Keypoint KeypointFromColumns(const std::vector<float>& v) {
  Keypoint k;
  k.x = v[0];
  k.y = v[1];
  if (v.size() == kScaleOrientationColumns) {
    k.scale = v[2];
    k.orientation = v[3];
  } else if (v.size() == kAffineColumns) {
    // l1, l2 are the semi-axes of the affine ellipse: the circle of equal area has radius
    // sqrt(l1 l2), and phi is the direction of the major axis.
    k.scale = std::sqrt(std::abs(v[2] * v[3]));
    k.orientation = v[4];
  }
  return k;
}

}  // namespace

namespace {

// A token as an error line can show it: quoted when it is short printable text, else described
// (a binary file's bytes would garble the terminal).
std::string QuotedToken(std::string_view token) {
  constexpr size_t kMaxShown = 32;
  const bool printable = std::all_of(token.begin(), token.end(), [](char c) { return c >= 0x20 && c < 0x7f; });
  if (printable && token.size() <= kMaxShown) return "'" + std::string(token) + "'";
  return printable ? "a " + std::to_string(token.size()) + "-character token" : "binary data";
}

}  // namespace

std::vector<Keypoint> ReadFeatFile(const fs::path& path) {
  const std::string text = ReadFileToString(path, false);
  const std::string source = path.string();
  std::vector<Keypoint> keypoints;
  size_t columns = 0;  // fixed by the first non-blank line
  std::vector<float> values;
  openmvg_text::ForEachLine(text, [&](std::string_view line, size_t line_number) {
    const std::vector<std::string_view> tokens = openmvg_text::SplitWhitespace(line);
    if (tokens.empty()) return;
    const std::string where = "line " + std::to_string(line_number) + ": ";
    if (columns == 0) {
      columns = tokens.size();
      if (columns != kPointColumns && columns != kScaleOrientationColumns && columns != kAffineColumns) {
        throw FileError(source,
                        where + "expected 2, 4 or 8 numbers per feature, found " + std::to_string(columns));
      }
    } else if (tokens.size() != columns) {
      throw FileError(source, where + "expected " + std::to_string(columns) +
                                  " numbers like the first line, found " + std::to_string(tokens.size()));
    }
    values.resize(columns);
    for (size_t c = 0; c < columns; ++c) {
      if (!openmvg_text::ParseFloat(tokens[c], &values[c]) || !std::isfinite(values[c])) {
        throw FileError(source, where + QuotedToken(tokens[c]) + " is not a finite number");
      }
    }
    keypoints.push_back(KeypointFromColumns(values));
  });
  return keypoints;
}

void WriteFeatFile(const fs::path& path, const std::vector<Keypoint>& keypoints) {
  WriteFileAtomically(path, false, [&](std::ostream& out) {
    for (const Keypoint& k : keypoints) {
      out << openmvg_text::FormatFloat(k.x) << ' ' << openmvg_text::FormatFloat(k.y) << ' '
          << openmvg_text::FormatFloat(k.scale) << ' ' << openmvg_text::FormatFloat(k.orientation) << '\n';
    }
  });
}

std::vector<Descriptor> ReadDescFile(const fs::path& path) {
  const std::string bytes = ReadFileToString(path);
  const std::string source = path.string();
  // Same fixed-width little-endian reading as COLMAP's binary files.
  colmap_binary::Reader reader(bytes, source);
  const auto count = reader.Read<uint64_t>();
  // Compare sizes before allocating, so a corrupt count cannot ask for terabytes.
  const size_t descriptor_bytes = bytes.size() - sizeof(uint64_t);
  if (descriptor_bytes % kDescriptorSize != 0 || descriptor_bytes / kDescriptorSize != count) {
    throw FileError(source, "holds " + std::to_string(descriptor_bytes) +
                                " descriptor bytes for a count of " + std::to_string(count) +
                                " (expected count x " + std::to_string(kDescriptorSize) +
                                " bytes of SIFT_Regions; truncated or another regions type?)");
  }
  std::vector<Descriptor> descriptors(count);
  for (Descriptor& d : descriptors) d = reader.Read<Descriptor>();
  return descriptors;
}

void WriteDescFile(const fs::path& path, const std::vector<Descriptor>& descriptors) {
  WriteFileAtomically(path, true, [&](std::ostream& out) {
    colmap_binary::Write<uint64_t>(out, descriptors.size());
    for (const Descriptor& d : descriptors) out.write(reinterpret_cast<const char*>(d.data()), d.size());
  });
}

ImageDescriberInfo ReadImageDescriber(const fs::path& path) {
  const std::string source = path.string();
  const nlohmann::json json = nlohmann::json::parse(ReadFileToString(path, false), nullptr, false);
  if (json.is_discarded() || !json.is_object()) throw FileError(source, "not a JSON object");
  // cereal writes the polymorphic name on the first object of each type, which both entries are.
  const auto polymorphic_name = [&](const char* key) {
    const auto entry = json.find(key);
    if (entry == json.end() || !entry->is_object())
      throw FileError(source, std::string("missing \"") + key + "\"");
    const auto name = entry->find("polymorphic_name");
    if (name == entry->end() || !name->is_string()) {
      throw FileError(source, std::string("\"") + key + "\" has no polymorphic_name");
    }
    return name->get<std::string>();
  };
  return {polymorphic_name("image_describer"), polymorphic_name("regions_type")};
}

void RequireSiftRegions(const ImageDescriberInfo& info, const fs::path& path) {
  if (info.regions_type != kSiftRegionsType) {
    throw FileError(path.string(),
                    "regions type " + info.regions_type + " (from " + info.describer_name +
                        ") is not supported; PruneSfM reads SIFT_Regions (128-byte descriptors)");
  }
}

void WriteSiftImageDescriber(const fs::path& path, const SiftDescriberParams& params) {
  using Json = nlohmann::ordered_json;  // cereal's member order, not alphabetical
  // The polymorphic ids are cereal's per-archive type numbers with the "first occurrence" bit.
  constexpr uint64_t kFirstTypeId = 0x80000001u;
  constexpr uint64_t kSecondTypeId = 0x80000002u;
  Json sift;
  // OpenMVG stores the thresholds as float and cereal widens them to double.
  sift["params"] = Json{{"first_octave", params.first_octave},
                        {"num_octaves", params.num_octaves},
                        {"num_scales", params.num_scales},
                        {"edge_threshold", static_cast<double>(params.edge_threshold)},
                        {"peak_threshold", static_cast<double>(params.peak_threshold)},
                        {"root_sift", params.root_sift}};
  sift["bOrientation"] = !params.upright;
  Json regions_data;
  regions_data["value0"] = Json::array();
  regions_data["value1"] = Json::array();
  const auto polymorphic = [](uint64_t id, const char* name, Json data) {
    Json entry;
    entry["polymorphic_id"] = id;
    entry["polymorphic_name"] = name;
    entry["ptr_wrapper"] = Json{{"valid", 1}, {"data", std::move(data)}};
    return entry;
  };
  Json root;
  root["image_describer"] = polymorphic(kFirstTypeId, "SIFT_Image_describer", std::move(sift));
  root["regions_type"] = polymorphic(kSecondTypeId, kSiftRegionsType, std::move(regions_data));
  const std::string text = root.dump(4);  // cereal indents by 4 and ends without a newline
  WriteFileAtomically(path, false, [&](std::ostream& out) { out << text; });
}

fs::path FeatureFilePath(const View& view, const fs::path& matches_dir, const std::string& extension) {
  fs::path name = fs::path(view.filename).stem();
  name += extension;
  return matches_dir / name;
}

FeaturesPerView ReadOpenMvgFeatures(const SfmData& sfm_data, const fs::path& matches_dir,
                                    bool with_descriptors, const ProgressCallback& progress) {
  const fs::path describer_path = matches_dir / kImageDescriberFileName;
  if (with_descriptors && fs::exists(describer_path)) {
    RequireSiftRegions(ReadImageDescriber(describer_path), describer_path);
  }
  FeaturesPerView features;
  size_t done = 0;
  for (const auto& [view_id, view] : sfm_data.views) {
    ReportProgress(progress, "Reading features", done++, sfm_data.views.size());
    FeatureSet& set = features[view_id];
    set.keypoints = ReadFeatFile(FeatureFilePath(view, matches_dir, ".feat"));
    if (!with_descriptors) continue;
    const fs::path desc_path = FeatureFilePath(view, matches_dir, ".desc");
    set.descriptors = ReadDescFile(desc_path);
    if (set.descriptors.size() != set.keypoints.size()) {
      throw FileError(desc_path.string(), "holds " + std::to_string(set.descriptors.size()) +
                                              " descriptors but the .feat file has " +
                                              std::to_string(set.keypoints.size()) + " features");
    }
  }
  ReportProgress(progress, "Reading features", done, sfm_data.views.size());
  return features;
}

void WriteOpenMvgFeatures(const SfmData& sfm_data, const FeaturesPerView& features,
                          const fs::path& matches_dir, const ProgressCallback& progress) {
  // Validate everything before the first write, so bad input leaves the directory untouched.
  std::map<fs::path, IndexT> view_of_feat_file;
  for (const auto& [view_id, view] : sfm_data.views) {
    const fs::path feat = FeatureFilePath(view, matches_dir, ".feat");
    const auto [it, inserted] = view_of_feat_file.emplace(feat, view_id);
    if (!inserted) {
      throw FileError(feat.string(),
                      "views " + std::to_string(it->second) + " and " + std::to_string(view_id) +
                          " have the same image basename; OpenMVG cannot tell their features apart");
    }
  }
  for (const auto& [view_id, set] : features) {
    if (sfm_data.views.count(view_id) == 0) {
      throw FileError(matches_dir.string(),
                      "features given for view " + std::to_string(view_id) + " which is not in the scene");
    }
    if (!set.descriptors.empty() && set.descriptors.size() != set.keypoints.size()) {
      throw FileError(FeatureFilePath(sfm_data.views.at(view_id), matches_dir, ".desc").string(),
                      "view " + std::to_string(view_id) + " has " + std::to_string(set.descriptors.size()) +
                          " descriptors for " + std::to_string(set.keypoints.size()) + " keypoints");
    }
  }
  const FeatureSet no_features;
  size_t done = 0;
  for (const auto& [view_id, view] : sfm_data.views) {
    ReportProgress(progress, "Writing features", done++, sfm_data.views.size());
    const auto found = features.find(view_id);
    const FeatureSet& set = found == features.end() ? no_features : found->second;
    WriteFeatFile(FeatureFilePath(view, matches_dir, ".feat"), set.keypoints);
    // A .desc must match its .feat in count; keypoints without descriptors get none.
    if (set.descriptors.size() == set.keypoints.size()) {
      WriteDescFile(FeatureFilePath(view, matches_dir, ".desc"), set.descriptors);
    }
  }
  WriteSiftImageDescriber(matches_dir / kImageDescriberFileName);
  ReportProgress(progress, "Writing features", done, sfm_data.views.size());
}

}  // namespace sfm_pruning
