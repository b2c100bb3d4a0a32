// openFile/closeFile for post scripts: a post writes files beside its main program (the SPF
// subprograms a SINUMERIK main program calls). Each is kept in memory; PostProcessor hands them
// out with the run's output, or writes them beside the output file when the whole run succeeded.
#include "post/detail/ScriptBindings.h"

#include <QJSEngine>

#include <algorithm>
#include <cctype>

namespace camwb::post {

namespace {

bool plainFileName(const std::string& name)
{
    return !name.empty() && name.size() <= 128 && name.front() != '.' &&
           std::all_of(name.begin(), name.end(), [](char c) {
               return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
           });
}

bool sameName(const std::string& a, const std::string& b)
{
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

}  // namespace

void ScriptKernel::openFile(const QJSValue& nameValue)
{
    const std::string name = nameValue.toString().toStdString();
    if (!nameValue.isString() || !plainFileName(name)) {
        m_engine->throwError(QJSValue::TypeError,
                             QStringLiteral("openFile(name): a plain file name (A-Z, a-z, 0-9, '_', '-', '.', not "
                                            "starting with '.', no folder), got '%1'")
                                 .arg(nameValue.toString()));
        return;
    }
    if (m_open >= 0) {
        m_engine->throwError(QJSValue::GenericError,
                             QString::fromStdString("openFile(\"" + name + "\") while \"" + openCompanion() +
                                                    "\" is open: closeFile() first"));
        return;
    }
    for (const CompanionWriter& file : m_companions) {
        if (sameName(file.name, name)) {
            m_engine->throwError(QJSValue::GenericError,
                                 QString::fromStdString("openFile(\"" + name + "\"): the run already wrote \"" +
                                                        file.name + "\" (each file once)"));
            return;
        }
    }
    m_companions.push_back({name, m_writer.restartedNumbering()});
    m_open = static_cast<int>(m_companions.size()) - 1;
}

void ScriptKernel::closeFile()
{
    if (m_open < 0) {
        m_engine->throwError(QJSValue::GenericError, QStringLiteral("closeFile() without an openFile()"));
        return;
    }
    m_open = -1;
}

}  // namespace camwb::post
