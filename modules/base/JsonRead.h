// Reading typed fields out of JSON documents (job files, machine files) with messages that say
// where: "job.tools[0].diameter: expected a number". Field readers throw JsonFieldError inside a
// reader; the reader's public function turns it into a base::Error (exceptions stay in the module).
#pragma once

#include "base/Result.h"
#include "base/Vec.h"

#include <nlohmann/json.hpp>

#include <string>

namespace camwb::base::jsonread {

using Json = nlohmann::json;

struct JsonFieldError {
    std::string message;
};

const Json& member(const Json& object, const char* key, const std::string& where);
// nullptr when the key is absent (throws when `object` is not an object).
const Json* optionalMember(const Json& object, const char* key, const std::string& where);
double number(const Json& object, const char* key, const std::string& where);
int integer(const Json& object, const char* key, const std::string& where);  // within int's range
// `value` (read as a number, e.g. from text "3") as a count: a whole number >= 0 within int's range.
int count(double value, const std::string& where);
bool boolean(const Json& object, const char* key, const std::string& where);
std::string text(const Json& object, const char* key, const std::string& where);
Vec3 vec3(const Json& object, const char* key, const std::string& where);

// Parses `content`; malformed JSON gives an Error with the line and column of the fault.
Result<Json> parse(const std::string& content, const std::string& path);

}  // namespace camwb::base::jsonread
