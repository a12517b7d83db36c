#pragma once
// One option-check path for every module: an options struct declares each INI key once (name, field,
// allowed range or values, help text) in an OptionTable, which then reads the key strictly (MRPT reads
// "abc" as 0), checks its range, writes it back with its help as a comment, and lists it for the docs.
// Errors are OptionErrors naming the section and key; whoever read the file adds where the value came
// from (the file or --set, see RunConfig).
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CLoadableOptions.h>
#include <vlo/core/error.h>

#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace vlo
{
/// A value that an options struct refuses: `[section] key: problem` (section empty when the struct
/// was filled in code rather than read from a section).
class OptionError : public InputError
{
   public:
	OptionError(const std::string& section, const std::string& key, const std::string& problem)
		: InputError((section.empty() ? "" : "[" + section + "] ") + key, problem), key_(key), problem_(problem)
	{
	}
	const std::string& key() const { return key_; }
	const std::string& problem() const { return problem_; }

   private:
	std::string key_, problem_;
};

/// Bounds of a numeric option, written as the docs show them: "> 0", ">= 1", "(0, 1]", "[19, 100)", or
/// "any".
struct Range
{
	double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
	bool lo_open = false, hi_open = false;
	std::string written;

	/// Throws std::logic_error for text of another form (a programmer's error, caught by the tests).
	static Range parse(const std::string& text);
	bool contains(double v) const;
	/// "must be > 0", "must be in (0, 1]"
	std::string text() const;
};

/// One declared key, as the docs list it.
struct OptionRow
{
	std::string key, default_text, allowed, help;
};

/// The keys of one options struct. Every key is declared the same way, `t.add(key, field, allowed, help)`:
/// `allowed` is a Range for numbers (and for each number of a list), "a | b | c" for a string that must
/// be one of those words, "any" for any number or text, "true | false" for a flag.
class OptionTable
{
   public:
	void add(const char* key, double& field, const char* allowed, const char* help);
	void add(const char* key, int& field, const char* allowed, const char* help);
	void add(const char* key, bool& field, const char* allowed, const char* help);
	void add(const char* key, std::string& field, const char* allowed, const char* help);
	void add(const char* key, std::vector<double>& field, const char* allowed, const char* help);
	/// One of the named values of an enum.
	template <class E>
	void choice(const char* key, E& field, std::vector<std::pair<std::string, E>> names, const char* help);

	/// Reads every declared key present in `section` (absent keys keep their value), checking type and
	/// range; throws OptionError.
	void load(const mrpt::config::CConfigFileBase& c, const std::string& section);
	/// Checks the current values (options built in code); throws OptionError without a section.
	void check() const;
	/// Writes every key with its help as a comment, padded as MRPT_SAVE_CONFIG_VAR_COMMENT does.
	void save(mrpt::config::CConfigFileBase& c, const std::string& section) const;
	std::vector<OptionRow> rows() const;

	struct Entry
	{
		std::string key, help, allowed;
		std::function<void(const std::string& text)> parse;  ///< sets the field or throws the problem as a string
		std::function<std::string()> check;  ///< "" or the problem with the current value
		std::function<void(mrpt::config::CConfigFileBase&, const std::string& section, const std::string& key,
			const std::string& help)>
			save;
	};
	/// A key of a kind the helpers above do not cover.
	void add(Entry e) { entries_.push_back(std::move(e)); }

   private:
	std::vector<Entry> entries_;
};

/// "'x' is not one of a, b, c", with a suggestion when `x` looks like a typo of one of them.
std::string notOneOf(const std::string& text, const std::vector<std::string>& allowed);

template <class E>
void OptionTable::choice(const char* key, E& field, std::vector<std::pair<std::string, E>> names, const char* help)
{
	std::vector<std::string> allowed;
	std::string listed;
	for (const auto& n : names)
	{
		allowed.push_back(n.first);
		listed += (listed.empty() ? "" : " | ") + n.first;
	}
	add({key, help, listed,
		[&field, names, allowed](const std::string& text) {
			for (const auto& n : names)
				if (n.first == text) return void(field = n.second);
			throw notOneOf(text, allowed);
		},
		[] { return std::string(); },
		[&field, names](mrpt::config::CConfigFileBase& c, const std::string& s, const std::string& k, const std::string& h) {
			for (const auto& n : names)
				if (n.second == field)
					c.write(s, k, n.first, mrpt::config::MRPT_SAVE_NAME_PADDING(), mrpt::config::MRPT_SAVE_VALUE_PADDING(), h);
		}});
}

/// An options struct read through its declarations. Derived structs list their keys in declare() and
/// put checks between keys ("max_range must exceed min_range") in checkRelations(): validation in one
/// place, whatever the section is called.
class OptionSet : public mrpt::config::CLoadableOptions
{
   public:
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& section) override;
	void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& section) const override;
	/// Ranges and relations of values set in code; throws OptionError without a section.
	void validate() const;
	/// The declared keys, for the docs.
	std::vector<OptionRow> rows() const;

   protected:
	virtual void declare(OptionTable& t) = 0;
	virtual void checkRelations() const {}
	/// For checkRelations(): throws OptionError for `key` unless `ok`.
	static void require(bool ok, const char* key, const std::string& problem);

   private:
	OptionTable table() const;
};

/// The options of a module that spans several sections, one OptionSet each.
class OptionGroup
{
   public:
	virtual ~OptionGroup() = default;
	/// Each part with its INI section.
	virtual std::vector<std::pair<std::string, OptionSet*>> parts() = 0;
	void load(const mrpt::config::CConfigFileBase& c);
	void save(mrpt::config::CConfigFileBase& c) const;
	void validate() const;  ///< throws OptionError naming the key
};

/// " (did you mean NAME?)" for the name among `known` nearest to `word` by edit distance, when it is
/// near enough to be a typo; else "".
std::string didYouMean(const std::string& word, const std::vector<std::string>& known);

/// `text` without leading and trailing blanks.
std::string trimmed(const std::string& text);

/// Up to 60 characters of `text` for a one-line message, unprintable ones shown as '?'.
std::string printable(const std::string& text);

/// "true"/"false" and their usual spellings; false when `text` is none of them.
bool parseBool(const std::string& text, bool& value);
}  // namespace vlo
