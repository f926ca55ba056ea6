// Reading a whole input file (see file.hpp).
// [OGC06-103 §7] [RFC7946]
// Preconditions: none.
#include "io/file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <system_error>

#include "core/error.hpp"
#include "io/text_util.hpp"

namespace mk {

std::string read_file(const std::string& path) {
  if (path.empty()) throw InvalidInput("no input file given (the path is empty)");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw InvalidInput("'" + path + "' is a directory, not a file");
  }
  // C stdio rather than iostreams: errno gives the reason ("No such file or directory",
  // "Permission denied") for the message.
  errno = 0;
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             &std::fclose);
  if (!file) {
    throw InvalidInput("cannot open '" + path + "': " +
                       (errno != 0 ? std::strerror(errno) : "unknown error"));
  }
  std::string content;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec) content.reserve(static_cast<std::size_t>(size));
  char buffer[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) content.append(buffer, got);
  if (std::ferror(file.get())) {
    throw InvalidInput("cannot read '" + path + "': " + std::strerror(errno));
  }
  return content;
}

std::string empty_input_message(std::string_view path) {
  return io_detail::quoted(path) +
         " is empty: expected a polygon in WKT, GeoJSON or native JSON (an empty polygon is "
         "written POLYGON EMPTY)";
}

}  // namespace mk
