// OpenMVG feature files (FORMATS.md §2.1-2.4): per view `<basename>.feat` (text keypoints) and
// `<basename>.desc` (binary SIFT descriptors) in the matches directory, plus
// `image_describer.json`, which tells OpenMVG's tools the regions type.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/util/progress.hpp"

namespace sfm_pruning {

// ---- .feat -----------------------------------------------------------------------------------
// One feature per line, line index = feature index. Accepted line layouts (all lines of a file
// must use the same one):
//   2 columns  x y                        (PointFeature)       scale 1, orientation 0
//   4 columns  x y scale orientation      (SIOPointFeature, what SIFT and AKAZE write)
//   8 columns  x y l1 l2 phi a b c        (AffinePointFeature) scale sqrt(l1 l2), orientation phi
// Blank lines are skipped. Throws Error naming the file and line on anything else.
std::vector<Keypoint> ReadFeatFile(const std::filesystem::path& path);
// Writes the 4-column layout, numbers as OpenMVG prints them (6 significant digits) unless more
// digits are needed to read back the exact float. Atomic.
void WriteFeatFile(const std::filesystem::path& path, const std::vector<Keypoint>& keypoints);

// ---- .desc -----------------------------------------------------------------------------------
// uint64 count (native byte order) followed by count x 128 bytes (SIFT_Regions descriptors).
std::vector<Descriptor> ReadDescFile(const std::filesystem::path& path);
void WriteDescFile(const std::filesystem::path& path, const std::vector<Descriptor>& descriptors);

// ---- image_describer.json --------------------------------------------------------------------
// Parameters of OpenMVG's SIFT_Image_describer, defaults as main_ComputeFeatures uses them.
struct SiftDescriberParams {
  int first_octave = 0;
  int num_octaves = 6;
  int num_scales = 3;
  float edge_threshold = 10.f;
  float peak_threshold = 0.04f;
  bool root_sift = true;
  bool upright = false;  // OpenMVG's -u: writes "bOrientation": false
};

struct ImageDescriberInfo {
  std::string describer_name;  // e.g. "SIFT_Image_describer"
  std::string regions_type;    // e.g. "SIFT_Regions"
};

inline constexpr char kImageDescriberFileName[] = "image_describer.json";
inline constexpr char kSiftRegionsType[] = "SIFT_Regions";

// Reports the describer and regions type names. Throws Error when the file is not an
// image_describer.json (missing keys, not JSON).
ImageDescriberInfo ReadImageDescriber(const std::filesystem::path& path);
// Throws Error when `info` names a regions type other than SIFT_Regions: the others (AKAZE float,
// LIOP, binary) have descriptors PruneSfM cannot use.
void RequireSiftRegions(const ImageDescriberInfo& info, const std::filesystem::path& path);
// Writes the file exactly as cereal does for a SIFT_Image_describer with SIFT_Regions. Atomic.
void WriteSiftImageDescriber(const std::filesystem::path& path, const SiftDescriberParams& params = {});

// ---- A whole project -------------------------------------------------------------------------
// `<matches_dir>/<filename of the view without directory and extension><extension>`, the name
// OpenMVG's features provider looks for. `extension` includes the dot (".feat", ".desc").
std::filesystem::path FeatureFilePath(const View& view, const std::filesystem::path& matches_dir,
                                      const std::string& extension);

// Reads the .feat (and, if `with_descriptors`, the .desc) of every view of `sfm_data`. With
// descriptors, an image_describer.json in `matches_dir` must name SIFT_Regions (when it is absent
// SIFT is assumed, as OpenMVG does). Throws Error naming the file when one is missing or
// unreadable, or when a .desc count differs from its .feat count.
FeaturesPerView ReadOpenMvgFeatures(const SfmData& sfm_data, const std::filesystem::path& matches_dir,
                                    bool with_descriptors, const ProgressCallback& progress = {});

// Writes a .feat for every view of `sfm_data` (empty for views absent from `features`), a .desc
// for every view that has descriptors or no keypoints, and image_describer.json (SIFT). Each file
// is atomic. Throws Error when two views share a basename, when `features` names a view absent
// from `sfm_data`, or when descriptors and keypoints differ in number.
void WriteOpenMvgFeatures(const SfmData& sfm_data, const FeaturesPerView& features,
                          const std::filesystem::path& matches_dir, const ProgressCallback& progress = {});

}  // namespace sfm_pruning
