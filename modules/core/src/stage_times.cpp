#include <vlo/core/stage_times.h>

#include <stdexcept>

namespace vlo
{
StageTimes::StageTimes(const std::vector<std::string>& stages)
{
	for (const auto& s : stages) stages_.emplace_back(s, 0.0);
}

std::size_t StageTimes::index(const std::string& stage) const
{
	for (std::size_t i = 0; i < stages_.size(); ++i)
		if (stages_[i].first == stage) return i;
	throw std::logic_error("StageTimes: undeclared stage '" + stage + "'");
}

void StageTimes::add(const std::string& stage, double ms) { stages_[index(stage)].second += ms; }

double StageTimes::ms(const std::string& stage) const { return stages_[index(stage)].second; }

double StageTimes::total() const
{
	double sum = 0;
	for (const auto& s : stages_) sum += s.second;
	return sum;
}
}  // namespace vlo
