// include("name") for post scripts: code several posts share (a dialect's cycles, its header)
// lives once in a post folder's include/ and is evaluated in the including post's global scope.
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

}  // namespace

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
    std::vector<std::string> dirs{(fs::path(m_postFile).parent_path() / "include").string()};
    for (const base::DataDir& dir : defaultPostDirs())
        dirs.push_back((fs::path(dir.path) / "include").string());
    auto path = base::findDataFile("post include", name, ".js", dirs);
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
