// PostContext from the environment and the UTC date format of post headers.
#include "post/PostProcessor.h"

#include "camwb_version.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <ctime>

namespace camwb::post {

namespace {

std::string environment(const char* name)
{
    const char* value = std::getenv(name);
    return value ? std::string(value) : std::string();
}

}  // namespace

PostContext PostContext::fromEnvironment(std::string programName)
{
    PostContext context;
    context.programName = std::move(programName);
    // Reproducible builds convention: SOURCE_DATE_EPOCH pins the clock.
    context.dateEpochSeconds = static_cast<std::int64_t>(std::time(nullptr));
    const std::string epoch = environment("SOURCE_DATE_EPOCH");
    if (!epoch.empty()) {
        char* end = nullptr;
        errno = 0;
        const long long value = std::strtoll(epoch.c_str(), &end, 10);
        if (errno == 0 && end && *end == '\0')
            context.dateEpochSeconds = value;
    }
    context.user = environment("CAMWB_USER");
    if (context.user.empty())
        context.user = environment("USER");
    if (context.user.empty())
        context.user = "unknown";
    context.version = CAMWB_VERSION;
    return context;
}

std::string formatDateUtc(std::int64_t epochSeconds)
{
    const std::time_t time = static_cast<std::time_t>(epochSeconds);
    std::tm utc{};
    gmtime_r(&time, &utc);
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%02d.%02d.%04d %02d:%02d:%02d", utc.tm_mday, utc.tm_mon + 1,
                  utc.tm_year + 1900, utc.tm_hour, utc.tm_min, utc.tm_sec);
    return buffer;
}

}  // namespace camwb::post
