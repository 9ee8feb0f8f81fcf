#include "radiometry/scene/GltfExternalFiles.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string_view>

#include <nlohmann/json.hpp>

#include "radiometry/common/Error.h"

namespace radiant::detail {
namespace {

std::string describeBytes(std::uint64_t bytes) {
    char text[48];
    if (bytes < 10'000)
        std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
    else
        std::snprintf(text, sizeof text, "%.3g MB", static_cast<double>(bytes) / 1e6);
    return text;
}

/// What a non-regular file is, for "is a directory, not a file".
std::string kindOf(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

/// An open descriptor, closed on every path out.
struct Descriptor {
    int fd = -1;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

/// Opens without blocking (a FIFO's open would wait for a writer forever) and checks what was
/// opened, not what the name pointed to a moment before. Empty string: fine; else the complaint.
std::string openRegular(const std::string& path, std::uint64_t byteBudget, Descriptor& file, std::uint64_t& size) {
    file.fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (file.fd < 0) return errno == ENOENT ? "not found" : std::string("cannot be opened: ") + std::strerror(errno);
    struct stat info {};
    if (::fstat(file.fd, &info) != 0) return std::string("cannot be inspected: ") + std::strerror(errno);
    if (!S_ISREG(info.st_mode)) return "is " + kindOf(info.st_mode) + ", not a file";
    size = static_cast<std::uint64_t>(info.st_size);
    if (size > byteBudget) return "is " + describeBytes(size) + "; the loader's budget is " + describeBytes(byteBudget) + " per file";
    return {};
}

/// Reads exactly `size` bytes; a file that shrank while being read is an error, not a short buffer.
std::string readAll(const Descriptor& file, std::uint64_t size, std::vector<unsigned char>& out) {
    out.resize(static_cast<std::size_t>(size));
    std::size_t done = 0;
    while (done < out.size()) {
        const ssize_t got = ::read(file.fd, out.data() + done, out.size() - done);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) return std::string("read failed: ") + std::strerror(errno);
        if (got == 0) return "ended after " + describeBytes(done) + " of " + describeBytes(size);
        done += static_cast<std::size_t>(got);
    }
    return {};
}

/// As tinygltf decodes a URI before opening it ('+' is a space, %XX a byte), so we check the file
/// it will open.
std::string decodeUri(const std::string& uri) {
    const auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return 0;
    };
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') {
            out += ' ';
        } else if (uri[i] == '%' && uri.size() > i + 2) {
            out += static_cast<char>((hex(uri[i + 1]) << 4) | hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

/// The JSON text of a .gltf, or of a .glb's first chunk; empty when there is none to find.
std::string_view jsonText(std::span<const unsigned char> bytes) {
    const auto text = [&](std::size_t from, std::size_t length) {
        return std::string_view(reinterpret_cast<const char*>(bytes.data()) + from, length);
    };
    if (bytes.size() < 4 || !(bytes[0] == 'g' && bytes[1] == 'l' && bytes[2] == 'T' && bytes[3] == 'F'))
        return text(0, bytes.size());
    if (bytes.size() < 20) return {};
    const std::size_t length = static_cast<std::size_t>(bytes[12]) | static_cast<std::size_t>(bytes[13]) << 8 |
                               static_cast<std::size_t>(bytes[14]) << 16 | static_cast<std::size_t>(bytes[15]) << 24;
    if (length > bytes.size() - 20) return {};
    return text(20, length);
}

/// Whether any "uri" in the JSON text may name a file (is not a data: URI): most scenes embed
/// everything, and then the text need not be parsed twice. A key spelt with escapes slips past this
/// scan, and then sceneFolderFileSystem's checks still hold.
bool mayNameFiles(std::string_view json) {
    constexpr std::string_view key = "\"uri\"";
    for (std::size_t at = json.find(key); at != std::string_view::npos; at = json.find(key, at + key.size())) {
        std::size_t value = at + key.size();
        while (value < json.size() && (json[value] == ' ' || json[value] == '\t' || json[value] == '\n' || json[value] == '\r' || json[value] == ':'))
            ++value;
        if (json.substr(value, 6) != "\"data:") return true;
    }
    return false;
}

bool isExternal(const nlohmann::json& resource) {
    const auto uri = resource.find("uri");
    return uri != resource.end() && uri->is_string() && uri->get<std::string>().rfind("data:", 0) != 0;
}

} // namespace

std::vector<unsigned char> readSceneFile(const std::string& path, std::uint64_t byteBudget) {
    Descriptor file;
    std::uint64_t size = 0;
    std::string problem = openRegular(path, byteBudget, file, size);
    if (problem.empty()) {
        std::vector<unsigned char> bytes;
        problem = readAll(file, size, bytes);
        if (problem.empty()) return bytes;
    }
    if (problem.rfind("is ", 0) == 0 && problem.find("budget") != std::string::npos) throw BudgetError({path, ""}, problem);
    throw RadiantError({path, ""}, problem == "not found" ? "no such file" : problem);
}

void checkExternalFiles(std::span<const unsigned char> bytes, const std::filesystem::path& folder,
                        const std::string& file, std::uint64_t byteBudget, std::vector<std::string>& warnings) {
    const std::string_view text = jsonText(bytes);
    if (!mayNameFiles(text)) return;
    const nlohmann::json gltf = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (!gltf.is_object()) return;  // tinygltf says what is wrong with it
    // tinygltf joins folder and URI with '/', so an absolute URI stays inside the folder too.
    const auto resolve = [&](const nlohmann::json& resource) { return folder.string() + "/" + decodeUri(resource["uri"].get<std::string>()); };

    if (const auto buffers = gltf.find("buffers"); buffers != gltf.end() && buffers->is_array())
        for (std::size_t b = 0; b < buffers->size(); ++b) {
            const nlohmann::json& buffer = (*buffers)[b];
            if (!buffer.is_object() || !isExternal(buffer)) continue;
            const SourceLocation where{file, "buffer " + std::to_string(b) + " '" + buffer["uri"].get<std::string>() + "'"};
            const auto stated = buffer.find("byteLength");
            const bool hasLength = stated != buffer.end() && stated->is_number_unsigned();
            const std::uint64_t byteLength = hasLength ? stated->get<std::uint64_t>() : 0;
            if (byteLength > byteBudget)
                throw BudgetError(where, "byteLength " + describeBytes(byteLength) + " is over the loader's budget of " + describeBytes(byteBudget) + " per file");
            Descriptor opened;
            std::uint64_t size = 0;
            const std::string problem = openRegular(resolve(buffer), byteBudget, opened, size);
            if (problem == "not found") throw RadiantError(where, "not found in " + folder.string());
            if (!problem.empty()) {
                if (problem.find("budget") != std::string::npos) throw BudgetError(where, problem);
                throw RadiantError(where, problem);
            }
            if (hasLength && size < byteLength)
                throw RadiantError(where, "is " + describeBytes(size) + ", shorter than its byteLength " + describeBytes(byteLength));
            if (hasLength && size > byteLength)
                throw RadiantError(where, "is " + describeBytes(size) + ", longer than its byteLength " + describeBytes(byteLength));
        }

    if (const auto images = gltf.find("images"); images != gltf.end() && images->is_array())
        for (std::size_t i = 0; i < images->size(); ++i) {
            const nlohmann::json& image = (*images)[i];
            if (!image.is_object() || !isExternal(image)) continue;
            const SourceLocation where{file, "image " + std::to_string(i) + " '" + image["uri"].get<std::string>() + "'"};
            Descriptor opened;
            std::uint64_t size = 0;
            const std::string problem = openRegular(resolve(image), byteBudget, opened, size);
            if (problem == "not found") {
                warnings.push_back(where.str() + ": not found in " + folder.string());
                continue;
            }
            if (!problem.empty()) {
                if (problem.find("budget") != std::string::npos) throw BudgetError(where, problem);
                throw RadiantError(where, problem);
            }
        }
}

tinygltf::FsCallbacks sceneFolderFileSystem(const std::uint64_t& byteBudget) {
    tinygltf::FsCallbacks callbacks{};
    callbacks.FileExists = [](const std::string& path, void*) {
        struct stat info {};
        return !path.empty() && path.front() == '/' && ::stat(path.c_str(), &info) == 0;
    };
    callbacks.ExpandFilePath = [](const std::string& path, void*) { return path; };
    callbacks.ReadWholeFile = [](std::vector<unsigned char>* out, std::string* error, const std::string& path, void* budget) {
        Descriptor file;
        std::uint64_t size = 0;
        std::string problem = openRegular(path, *static_cast<const std::uint64_t*>(budget), file, size);
        if (problem.empty()) problem = readAll(file, size, *out);
        if (!problem.empty() && error) *error += problem;
        return problem.empty();
    };
    callbacks.WriteWholeFile = [](std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; };
    callbacks.user_data = const_cast<std::uint64_t*>(&byteBudget);
    return callbacks;
}

} // namespace radiant::detail
