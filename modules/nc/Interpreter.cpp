#include "nc/Interpreter.h"

#include "base/AtomicFile.h"
#include "kinematics/LimitCheck.h"
#include "nc/detail/Dialects.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

namespace camwb::nc {

namespace {

std::string withCase(std::string_view name, int (*convert)(int))
{
    std::string out(name);
    std::transform(out.begin(), out.end(), out.begin(),
                   [convert](unsigned char c) { return static_cast<char>(convert(c)); });
    return out;
}

}  // namespace

ProgramResolver folderResolver(std::string folder, std::vector<std::string> extensions)
{
    return [folder = std::move(folder),
            extensions = std::move(extensions)](std::string_view name) -> std::optional<ProgramSource> {
        namespace fs = std::filesystem;
        if (name.empty() || name.find('/') != std::string_view::npos)
            return std::nullopt;
        const std::string spellings[] = {std::string(name), withCase(name, ::toupper), withCase(name, ::tolower)};
        std::vector<std::string> suffixes{""};
        for (const std::string& ext : extensions) {
            suffixes.push_back(ext);
            suffixes.push_back(withCase(ext, ::toupper));
        }
        for (const std::string& spelling : spellings) {
            for (const std::string& suffix : suffixes) {
                // Without a folder the bare name, so that messages name the file as the caller did.
                const fs::path candidate =
                    folder.empty() ? fs::path(spelling + suffix) : fs::path(folder) / (spelling + suffix);
                std::error_code ec;
                if (!fs::is_regular_file(candidate, ec))
                    continue;
                auto text = base::readPlainTextFile(candidate.string());
                if (text)
                    return ProgramSource{candidate.string(), std::move(text).value()};
            }
        }
        return std::nullopt;
    };
}

namespace {

InterpretResult interpretDialect(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink)
{
    if (options.clFormat)
        return detail::importCl(text, options, sink);
    switch (options.dialect) {
    case Dialect::Sinumerik:
        return detail::interpretSinumerik(text, options, sink);
    case Dialect::Heidenhain:
        return detail::interpretHeidenhain(text, options, sink);
    case Dialect::Iso:
        return detail::interpretIso(text, options, sink);
    }
    return {};
}

}  // namespace

InterpretResult interpret(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink)
{
    if (!options.machine || !options.checkLimits)
        return interpretDialect(text, options, sink);
    // The same check the post kernel makes, on what the control would do, whatever the dialect.
    kinematics::LimitCheck check(*options.machine, sink);
    InterpretResult result = interpretDialect(text, options, check);
    if (!result.cancelled) {
        for (base::Diagnostic& d : check.ncDiagnostics(result.files))
            result.diagnostics.push_back(std::move(d));
    }
    return result;
}

ProgramResolver resolverBeside(const std::string& programPath, Dialect dialect)
{
    const std::string folder = std::filesystem::path(programPath).parent_path().string();
    return dialect == Dialect::Heidenhain ? folderResolver(folder, {".h"})
                                          : folderResolver(folder, {".spf", ".mpf", ".ngc", ".nc"});
}

InterpretResult interpretFile(const std::string& path, std::optional<Dialect> dialect, InterpretOptions options,
                              toolpath::MachineSink& sink)
{
    auto text = base::readPlainTextFile(path);
    if (!text) {
        InterpretResult failed;
        failed.files.push_back(path);
        failed.diagnostics.push_back({Severity::Error, path, text.error().line, 0, text.error().message});
        return failed;
    }
    options.dialect = dialect ? *dialect : guessDialect(text.value(), path);
    if (!dialect && !options.clFormat)
        options.clFormat = toolpath::clFormatFromExtension(path);
    options.fileName = path;
    if (!options.resolveProgram)
        options.resolveProgram = resolverBeside(path, options.dialect);
    return interpret(text.value(), options, sink);
}

}  // namespace camwb::nc
