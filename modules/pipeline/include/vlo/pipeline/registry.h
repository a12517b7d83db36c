#pragma once
// Creates modules by the name given in the INI's [pipeline] section.
#include <vlo/core/error.h>

#include <functional>
#include <map>
#include <memory>
#include <string>

namespace vlo
{
template <class Base>
class Registry
{
   public:
	using Factory = std::function<std::unique_ptr<Base>()>;

	void add(const std::string& name, Factory f) { factories_[name] = std::move(f); }

	std::unique_ptr<Base> create(const std::string& name, const std::string& where) const
	{
		const auto it = factories_.find(name);
		if (it == factories_.end()) failInput(where, "unknown module '" + name + "' (known: " + names() + ")");
		return it->second();
	}

	std::string names() const
	{
		std::string s;
		for (const auto& [n, f] : factories_) s += (s.empty() ? "" : ", ") + n;
		return s;
	}

   private:
	std::map<std::string, Factory> factories_;
};
}  // namespace vlo
