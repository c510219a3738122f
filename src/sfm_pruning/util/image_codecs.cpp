#include "sfm_pruning/util/image_codecs.hpp"

#include <dlfcn.h>

#include <mutex>
#include <optional>
#include <system_error>

#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/image_file_integrity.hpp"

namespace sfm_pruning {
namespace {
namespace fs = std::filesystem;

using ReadFunction = int (*)(const char*, int, cv::Mat*, std::string*);
using WriteFunction = int (*)(const char*, const cv::Mat*, const std::vector<int>*, std::string*);
using EncodeFunction = int (*)(const char*, const cv::Mat*, const std::vector<int>*, std::vector<unsigned char>*,
                               std::string*);

struct Codecs {
  ReadFunction read = nullptr;
  WriteFunction write = nullptr;
  EncodeFunction encode = nullptr;
};

// Where the module may be: where this build put it, where `cmake --install` puts it, then beside
// the running executable.
std::vector<fs::path> ModuleCandidates() {
  std::vector<fs::path> candidates = {PRUNESFM_IMAGE_CODECS_MODULE, PRUNESFM_IMAGE_CODECS_MODULE_INSTALLED};
  std::error_code error;
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (!error) candidates.push_back(executable.parent_path() / fs::path(PRUNESFM_IMAGE_CODECS_MODULE).filename());
  return candidates;
}

template <typename Function>
Function Symbol(void* module, const char* name, const fs::path& path) {
  void* symbol = dlsym(module, name);
  if (symbol == nullptr) throw FileError(path.string(), std::string("image codecs module lacks ") + name);
  return reinterpret_cast<Function>(symbol);
}

Codecs LoadCodecs() {
  std::string problems;
  for (const fs::path& path : ModuleCandidates()) {
    // The module stays loaded for the life of the process.
    void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (module == nullptr) {
      problems += std::string(problems.empty() ? "" : "; ") + dlerror();
      continue;
    }
    Codecs codecs;
    codecs.read = Symbol<ReadFunction>(module, "prunesfm_codecs_read", path);
    codecs.write = Symbol<WriteFunction>(module, "prunesfm_codecs_write", path);
    codecs.encode = Symbol<EncodeFunction>(module, "prunesfm_codecs_encode", path);
    return codecs;
  }
  throw Error("cannot load the image codecs module: " + problems);
}

const Codecs& TheCodecs() {
  // A failed load throws out of the initialiser, so the next call tries again.
  static std::mutex mutex;
  static std::optional<Codecs> codecs;
  std::lock_guard<std::mutex> lock(mutex);
  if (!codecs) codecs = LoadCodecs();
  return *codecs;
}

// 1 / 0 as the module returns them; -1 becomes an ImageCodecError.
bool Outcome(int result, const std::string& error) {
  if (result < 0) throw ImageCodecError(error);
  return result > 0;
}

}  // namespace

cv::Mat ReadImageFile(const fs::path& path, int flags) {
  // A file cut short is reported here, before a codec prints its own warning or error.
  std::string bytes;
  try {
    bytes = ReadFileToString(path);
  } catch (const Error&) {
    return {};  // unreadable: imread would not decode it either
  }
  const std::string cut_short = ImageCutShortProblem(bytes);
  if (!cut_short.empty()) throw ImageCodecError(cut_short);
  cv::Mat image;
  std::string error;
  Outcome(TheCodecs().read(path.c_str(), flags, &image, &error), error);
  return image;
}

bool WriteImageFile(const fs::path& path, const cv::Mat& image, const std::vector<int>& parameters) {
  std::string error;
  return Outcome(TheCodecs().write(path.c_str(), &image, &parameters, &error), error);
}

bool EncodeImage(const std::string& extension, const cv::Mat& image, const std::vector<int>& parameters,
                 std::vector<unsigned char>* bytes) {
  std::string error;
  return Outcome(TheCodecs().encode(extension.c_str(), &image, &parameters, bytes, &error), error);
}

}  // namespace sfm_pruning
