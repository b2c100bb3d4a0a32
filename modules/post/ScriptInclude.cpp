// include("name") for post scripts: code several posts share (a dialect's cycles, its header)
// lives once in a post folder's include/ and is evaluated in the including post's global scope.
// readPostFile("sub/file") reads a file a post ships beside itself (NC code it copies), looked up
// in the same folders.
#include "base/AtomicFile.h"
#include "base/DataDirs.h"
#include "post/PostRegistry.h"
#include "post/detail/ScriptBindings.h"

#include <QJSEngine>

#include <algorithm>
#include <filesystem>

namespace camwb::post {

namespace fs = std::filesystem;

namespace {

bool plainName(const std::string& name)
{
    return !name.empty() && name.size() <= 64 && std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    });
}

// The folders a post's files are looked up in, in order: `sub` of the post's own folder, then of
// every post folder (a user's post may use what a built-in one ships).
std::vector<std::string> postFileDirs(const std::string& postFile, const std::string& sub)
{
    std::vector<std::string> dirs{(fs::path(postFile).parent_path() / sub).lexically_normal().string()};
    for (const base::DataDir& dir : defaultPostDirs())
        dirs.push_back((fs::path(dir.path) / sub).lexically_normal().string());
    return dirs;
}

// Why `path` cannot name a file inside a post folder; empty when it can.
std::string relativePathProblem(const std::string& path)
{
    if (path.empty())
        return "an empty path";
    if (path.front() == '/' || path.find('\\') != std::string::npos || path.find(':') != std::string::npos)
        return "an absolute path (or one with '\\' or ':'); a path relative to the post's folder is needed";
    for (const fs::path& part : fs::path(path)) {
        if (part == "..")
            return "a path with '..': only files inside the post folder can be read";
        if (part.empty() || part == ".")
            return "a path with an empty or '.' part";
    }
    return {};
}

// Whether `path` (existing) lies inside `dir` once links are followed.
bool insideFolder(const fs::path& path, const fs::path& dir)
{
    std::error_code ec;
    const fs::path real = fs::canonical(path, ec);
    const fs::path realDir = ec ? fs::path() : fs::canonical(dir, ec);
    if (ec)
        return false;
    const fs::path rest = real.lexically_relative(realDir);
    return !rest.empty() && *rest.begin() != "..";
}

}  // namespace

QString ScriptKernel::readPostFile(const QJSValue& relativePath)
{
    const std::string path = relativePath.toString().toStdString();
    const std::string problem = relativePath.isString() ? relativePathProblem(path) : "not a string";
    if (!problem.empty()) {
        m_engine->throwError(QJSValue::URIError, QString::fromStdString("readPostFile(\"" + path + "\"): " + problem));
        return {};
    }
    std::string searched;
    for (const std::string& dir : postFileDirs(m_postFile, "")) {
        const fs::path candidate = fs::path(dir) / path;
        std::error_code ec;
        searched += (searched.empty() ? "" : ", ") + dir;
        if (!fs::is_regular_file(candidate, ec))
            continue;
        if (!insideFolder(candidate, dir)) {
            m_engine->throwError(QJSValue::URIError,
                                 QString::fromStdString("readPostFile(\"" + path + "\"): " + candidate.string() +
                                                        " leads out of the post folder " + dir));
            return {};
        }
        const auto text = base::readTextFile(candidate.string());
        if (!text) {
            m_engine->throwError(QJSValue::URIError,
                                 QString::fromStdString("readPostFile(\"" + path + "\"): " + text.error().toString()));
            return {};
        }
        return QString::fromStdString(text.value());
    }
    m_engine->throwError(QJSValue::URIError,
                         QString::fromStdString("readPostFile(\"" + path + "\"): no such file in " + searched));
    return {};
}

void ScriptKernel::include(const QJSValue& nameValue)
{
    const std::string name = nameValue.toString().toStdString();
    if (!nameValue.isString() || !plainName(name)) {
        m_engine->throwError(
            QJSValue::TypeError,
            QStringLiteral("include(name): a plain name (a-z, 0-9, '_' or '-'), got '%1'").arg(nameValue.toString()));
        return;
    }
    if (std::find(m_included.begin(), m_included.end(), name) != m_included.end())
        return;  // once per run, as a second copy would only define the same functions again
    auto path = base::findDataFile("post include", name, ".js", postFileDirs(m_postFile, "include"));
    if (!path) {
        m_engine->throwError(QJSValue::URIError, QString::fromStdString(path.error().message));
        return;
    }
    const auto text = base::readTextFile(path.value());
    if (!text) {
        m_engine->throwError(QJSValue::URIError, QString::fromStdString(text.error().toString()));
        return;
    }
    m_included.push_back(name);
    const QJSValue result =
        m_engine->evaluate(QString::fromStdString(text.value()), QString::fromStdString(path.value()), 1);
    if (result.isError())
        m_engine->throwError(result);  // keeps the included file's name and line
}

}  // namespace camwb::post
