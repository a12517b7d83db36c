#pragma once
// How an EvalReport is shown: a table for people, JSON for scripts (keys in doc/EVALUATION.md).
#include <vlo/eval/evaluate.h>

#include <string>

namespace vlo::eval
{
std::string formatTable(const EvalReport& r);
std::string toJson(const EvalReport& r);
/// Written atomically: the file is complete or absent.
void writeJson(const std::string& path, const EvalReport& r);
}  // namespace vlo::eval
