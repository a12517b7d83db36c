// Issue 34, defect 8: a non-ASCII --title rendered as "??" per character (a '?' per UTF-8 byte).
#include <gtest/gtest.h>

#include "../src/hershey_text.h"

using namespace vlo;
using namespace vlo::viz;

TEST(HersheyText, AccentedLettersLoseTheirAccentsAndOtherCharactersAreOneQuestionMark)
{
	EXPECT_EQ(hersheyText("plain ASCII, 100 m"), "plain ASCII, 100 m");
	EXPECT_EQ(hersheyText("K\xC3\xB6ln \xC3\xBC"
						  "ber Stra\xC3\x9F"
						  "e"),
		"Koln uber Strasse");  // Köln über Straße
	EXPECT_EQ(hersheyText("5 \xC2\xB0"
						  "C, \xC5\x81\xC3\xB3"
						  "d\xC5\xBA"),
		"5 degC, Lodz");  // 5 °C, Łódź
	EXPECT_EQ(hersheyText("\xE6\x9D\xB1\xE4\xBA\xAC run"), "?? run");  // two CJK characters: one '?' each
	EXPECT_EQ(hersheyText("\xF0\x9F\x9A\x97!"), "?!");  // an emoji
	EXPECT_EQ(hersheyText("cut \xC3"), "cut ?");  // a truncated sequence does not read past the end
}
