#include "document/detail/ZipJson.h"

#include <minizip/unzip.h>

#include <array>
#include <memory>

namespace camwb::document::detail {

namespace {

constexpr std::uint64_t kMaxJsonBytes = 256ull << 20;  // a zip bomb is refused, not unpacked

struct Closer {
    void operator()(void* file) const { unzClose(file); }
};

bool endsWithJson(const std::string& name)
{
    constexpr std::string_view ext = ".json";
    if (name.size() < ext.size())
        return false;
    std::string tail = name.substr(name.size() - ext.size());
    for (char& c : tail)
        c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return tail == ext;
}

}  // namespace

base::Result<std::string> readJsonFromZip(const std::string& path)
{
    const std::unique_ptr<void, Closer> zip(unzOpen64(path.c_str()));
    if (!zip)
        return base::makeError("not a zip archive that can be read (a damaged or incomplete .tools file?)", path);
    std::string entry;
    unz_file_info64 info{};
    for (int at = unzGoToFirstFile(zip.get()); at == UNZ_OK; at = unzGoToNextFile(zip.get())) {
        std::array<char, 1024> name{};
        if (unzGetCurrentFileInfo64(zip.get(), &info, name.data(), name.size() - 1, nullptr, 0, nullptr, 0) != UNZ_OK)
            return base::makeError("the zip archive's list of files is damaged", path);
        if (endsWithJson(name.data())) {
            entry = name.data();
            break;
        }
    }
    if (entry.empty())
        return base::makeError("the zip archive holds no .json file (a Fusion 360 .tools holds tools.json)", path);
    if (info.uncompressed_size > kMaxJsonBytes)
        return base::makeError("'" + entry + "' in the zip archive is larger than a tool library can be", path);
    if (unzOpenCurrentFile(zip.get()) != UNZ_OK)
        return base::makeError("cannot open '" + entry + "' in the zip archive (damaged, or encrypted)", path);
    std::string text;
    std::array<char, 65536> buffer{};
    int read = 0;
    while ((read = unzReadCurrentFile(zip.get(), buffer.data(), buffer.size())) > 0) {
        text.append(buffer.data(), static_cast<std::size_t>(read));
        if (text.size() > kMaxJsonBytes) {
            unzCloseCurrentFile(zip.get());
            return base::makeError("'" + entry + "' in the zip archive is larger than a tool library can be", path);
        }
    }
    // The checksum is checked when the entry is closed, after all of it was read.
    const int closed = unzCloseCurrentFile(zip.get());
    if (read < 0 || closed != UNZ_OK)
        return base::makeError("'" + entry + "' in the zip archive is damaged (" +
                                   (closed == UNZ_CRCERROR ? std::string("its checksum does not match")
                                                           : "error " + std::to_string(read < 0 ? read : closed)) +
                                   ")",
                               path);
    return text;
}

}  // namespace camwb::document::detail
