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

namespace {

enum class Contents { any, text };

std::string read_stream(std::FILE* stream, const std::string& name, Contents contents, std::size_t reserve = 0) {
  std::string content;
  content.reserve(reserve);
  char buffer[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, stream)) > 0) {
    if (contents == Contents::text) {
      if (const void* nul = std::memchr(buffer, '\0', got)) {
        const auto at = content.size() + static_cast<std::size_t>(static_cast<const char*>(nul) - buffer);
        throw InvalidInput(name + " holds a NUL byte at offset " + std::to_string(at) +
                           ": binary data, not WKT, GeoJSON or JSON text");
      }
    }
    content.append(buffer, got);
  }
  if (std::ferror(stream)) throw InvalidInput("cannot read " + name + ": " + std::strerror(errno));
  return content;
}

std::string read_named_file(const std::string& path, Contents contents) {
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
  const auto size = std::filesystem::file_size(path, ec);
  return read_stream(file.get(), io_detail::quoted(path), contents, ec ? 0 : static_cast<std::size_t>(size));
}

}  // namespace

std::string read_file(const std::string& path) { return read_named_file(path, Contents::any); }

std::string read_text_file(const std::string& path) { return read_named_file(path, Contents::text); }

std::string read_text_stream(std::FILE* stream, const std::string& name) {
  return read_stream(stream, name, Contents::text);
}

std::string empty_input_message(std::string_view path) {
  return io_detail::quoted(path) +
         " is empty: expected a polygon in WKT, GeoJSON or native JSON (an empty polygon is "
         "written POLYGON EMPTY)";
}

}  // namespace mk
