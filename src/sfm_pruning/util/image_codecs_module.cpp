// The loadable module behind image_codecs.hpp: the only code linked against OpenCV's imgcodecs.
// C entry points, so the facade finds them by plain names; each catches OpenCV's exceptions,
// which must not cross the module boundary. Return values: 1 done, 0 OpenCV declined (could not
// decode, write or encode), -1 OpenCV threw (its message in *error).
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

extern "C" {

__attribute__((visibility("default"))) int prunesfm_codecs_read(const char* path, int flags, cv::Mat* image,
                                                                 std::string* error) {
  try {
    *image = cv::imread(path, flags);
    return image->empty() ? 0 : 1;
  } catch (const cv::Exception& e) {
    *error = e.err;
    return -1;
  }
}

__attribute__((visibility("default"))) int prunesfm_codecs_write(const char* path, const cv::Mat* image,
                                                                  const std::vector<int>* parameters,
                                                                  std::string* error) {
  try {
    return cv::imwrite(path, *image, *parameters) ? 1 : 0;
  } catch (const cv::Exception& e) {
    *error = e.err;
    return -1;
  }
}

__attribute__((visibility("default"))) int prunesfm_codecs_encode(const char* extension, const cv::Mat* image,
                                                                   const std::vector<int>* parameters,
                                                                   std::vector<unsigned char>* bytes,
                                                                   std::string* error) {
  try {
    return cv::imencode(extension, *image, *bytes, *parameters) ? 1 : 0;
  } catch (const cv::Exception& e) {
    *error = e.err;
    return -1;
  }
}

}  // extern "C"
