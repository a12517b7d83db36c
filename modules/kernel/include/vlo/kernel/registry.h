#pragma once
// Creates modules by the name given in the INI. Each module family (an interface class) has one
// registry; an implementation adds itself from its own source file with VLO_REGISTER_MODULE, which
// runs before main(). The file must be linked as an object (vlo_add_registered_module in CMake), or
// the linker would drop it from a static library since nothing names it.
#include <vlo/core/error.h>
#include <vlo/core/option_table.h>

#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vlo::kernel
{
template <class Base>
class Registry
{
   public:
	using Factory = std::function<std::unique_ptr<Base>()>;

	/// Returns true so that registration can initialise a static; a name taken twice is a
	/// programming error (two modules would answer to it).
	bool add(const std::string& name, Factory f)
	{
		if (!factories_.emplace(name, std::move(f)).second)
			throw std::logic_error("module '" + name + "' registered twice");
		return true;
	}

	/// `where` names the option that asked for it, for the error message.
	std::unique_ptr<Base> create(const std::string& name, const std::string& where) const
	{
		require(name, where);
		return factories_.at(name)();
	}

	/// Throws InputError naming `where` when no module is registered under `name`.
	void require(const std::string& name, const std::string& where) const
	{
		if (!factories_.count(name)) failInput(where, "unknown module '" + printable(name) + "' (known: " + names() + ")");
	}

	/// One new instance of every registered module, by name.
	std::vector<std::pair<std::string, std::unique_ptr<Base>>> createAll() const
	{
		std::vector<std::pair<std::string, std::unique_ptr<Base>>> all;
		for (const auto& [n, f] : factories_) all.emplace_back(n, f());
		return all;
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

/// The registry of a module family: one per interface class, shared by the whole program.
template <class Family>
Registry<Family>& registry()
{
	static Registry<Family> r;
	return r;
}
}  // namespace vlo::kernel

/// Registers `Class` (default-constructible, derived from `Family`) under `name`, e.g.
/// VLO_REGISTER_MODULE(LidarOdometryModule, "aloam", AloamModule). Use once per class, at namespace scope.
#define VLO_REGISTER_MODULE(Family, name, Class) \
	[[maybe_unused]] static const bool vlo_registered_##Class = ::vlo::kernel::registry<Family>().add(name, [] { return std::make_unique<Class>(); })
