// Procedural scene families: each seed draws a whole scene description (geometry, how much of it
// repeats and where the unique texture sits, the camera path, the capture conditions), so a
// benchmark can report accuracy over a distribution of scenes instead of a few fixed ones.
//
// Families (docs/synthetic_scenes.md, "Scene families"):
//   family_street     facades of 1-3 designs along a street, with or without gaps, one or two sides
//   family_courtyard  courtyards and rotundas whose wall repeats with 2-, 3-, 4- or 6-fold symmetry
//   family_object     a cup, box or package whose opposite faces print alike, seen on an orbit
//   family_desk       a desk with several identical copies of a boxed object
//   family_loop       a block loop with repeated buildings, driven twice (sequential + retrieval pairs)
//   family_control    one of the geometries above with every surface unique (no twins)
//
// Every draw comes from the seed's own parameter stream, so scene `family_X` with seed s is the
// same scene wherever and whenever it is generated.
#pragma once

#include <map>
#include <random>
#include <string>
#include <vector>

#include "sfm_pruning/eval/synthetic_layout.hpp"

namespace sfm_pruning {

// The family scene names, in documentation order.
std::vector<std::string> SyntheticFamilyNames();
bool IsSyntheticFamily(const std::string& scene);

// Records each draw by name, so the scene's summary says what was drawn.
class ParameterDraw {
 public:
  ParameterDraw(std::mt19937_64* rng, SceneDescription* description) : rng_(rng), description_(description) {}

  double Uniform(const std::string& name, double low, double high);
  int Integer(const std::string& name, int low, int high);  // both bounds included
  bool Chance(const std::string& name, double probability);
  std::string Choice(const std::string& name, const std::vector<std::string>& choices);
  // A value derived from draws, recorded beside them (e.g. a realised share).
  void Record(const std::string& name, double value) { description_->values[name] = value; }
  void Label(const std::string& name, const std::string& value) { description_->labels[name] = value; }

 private:
  std::mt19937_64* rng_;
  SceneDescription* description_;
};

// Draws the capture conditions of a family scene (views, focal, keypoint and descriptor noise,
// detection rate, clutter, outlier matches) into `options`, and records them.
void DrawFamilyCapture(SyntheticSceneOptions* options, SceneDescription* description);

// The layout of a family scene; the geometry's parameters are drawn from the seed's parameter
// stream and recorded in layout.description, the jitter comes from `rng` (the layout stream).
SceneLayout BuildFamilyLayout(const SyntheticSceneOptions& options, std::mt19937_64& rng);

// Family builders (one file each). `twins` false gives every copy its own texture: the
// family_control scenes.
SceneLayout BuildStreetFamilyLayout(const SyntheticSceneOptions& options, bool twins, ParameterDraw& draw,
                                    std::mt19937_64& rng);
SceneLayout BuildCourtyardFamilyLayout(const SyntheticSceneOptions& options, bool twins, ParameterDraw& draw,
                                       std::mt19937_64& rng);
SceneLayout BuildObjectFamilyLayout(const SyntheticSceneOptions& options, bool twins, ParameterDraw& draw,
                                    std::mt19937_64& rng);
SceneLayout BuildDeskFamilyLayout(const SyntheticSceneOptions& options, bool twins, ParameterDraw& draw,
                                  std::mt19937_64& rng);

// Density (points per m^2) that puts `share` of a scene's points on `unique_area_m2` of unique
// texture next to `repeated_points` points of repeated texture, within [min, max] per m^2.
double UniqueTextureDensity(double share, size_t repeated_points, double unique_area_m2, double min_density,
                            double max_density);

// The share of the layout's points whose appearance is unique (seen in one place only).
double UniquePointShare(const SceneLayout& layout);

}  // namespace sfm_pruning
