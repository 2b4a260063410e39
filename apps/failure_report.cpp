#include "apps/failure_report.h"

#include <algorithm>
#include <filesystem>
#include <new>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "lrsvo/graph/error.h"

namespace lrsvo::cli {
namespace {

// Messages of OpenCV and some file-system errors run over several lines.
std::string oneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

std::string describe(std::exception_ptr failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const Error& e) {
    return std::string("error: ") + e.what();
  } catch (const cv::Exception& e) {
    return "OpenCV error: " + e.err + (e.func.empty() ? "" : " (in " + e.func + ")");
  } catch (const std::filesystem::filesystem_error& e) {
    return std::string("file system error: ") + e.what();
  } catch (const nlohmann::json::exception& e) {
    return std::string("JSON error: ") + e.what();
  } catch (const std::bad_alloc&) {
    return "out of memory";
  } catch (const std::exception& e) {
    return std::string("error: ") + e.what();
  } catch (...) {
    return "unknown error";
  }
}

}  // namespace

std::string failureLine(const std::string& command, std::exception_ptr failure) {
  return oneLine("lrsvo" + (command.empty() ? std::string() : " " + command) + ": " + describe(failure));
}

}  // namespace lrsvo::cli
