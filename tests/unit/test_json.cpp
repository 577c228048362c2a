// The JSON writer's two halves (plugin/core/json.hpp): quoting, and the validator every JSON
// file passes before it is published (edp/lib/output.idp Publish).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "core/json.hpp"

using sma::json::quote;
using sma::json::validate;

TEST(JsonQuote, EscapesQuotesBackslashesAndControlCharacters) {
  EXPECT_EQ(quote("plain"), "\"plain\"");
  EXPECT_EQ(quote("it's a \"dir\""), "\"it's a \\\"dir\\\"\"");
  EXPECT_EQ(quote("a\\b"), "\"a\\\\b\"");
  EXPECT_EQ(quote("tab\there\nnew"), "\"tab\\there\\nnew\"");
  EXPECT_EQ(quote(std::string("nul\x01") + "x"), "\"nul\\u0001x\"");
}

TEST(JsonQuote, QuotedStringsAreValidDocumentsWhateverTheyHold) {
  // Every byte from 1 to 255 (UTF-8 and its fragments pass through as they are), in one string.
  std::string all;
  for (int c = 1; c < 256; ++c) all += (char)c;
  for (const std::string& s : {std::string("r\xc3\xa9sultats \xe2\x9c\x93"), std::string("; rm -rf /"),
                               std::string("\"'`$(x)"), all})
    EXPECT_EQ(validate("{\"mesh\": " + quote(s) + "}"), "") << s;
}

TEST(JsonValidate, AcceptsWhatTheScenesWrite) {
  EXPECT_EQ(validate("{\n  \"scene\": \"x\",\n  \"parameters\": {\"E\": 85000000000, \"nu\": 0.3, "
                     "\"tol\": 1e-09, \"neg\": -2.5E+3},\n  \"list\": [1, 2, [], {}], \"b\": true, \"n\": null\n}\n"),
            "");
}

TEST(JsonValidate, RefusesNonFiniteNumbersNamingTheKey) {
  // FreeFEM prints an overflowed real as inf / -inf and an undefined one as nan / -nan.
  for (const char* bad : {"inf", "-inf", "nan", "-nan"}) {
    const std::string error = validate(std::string("{\"a\": 1, \"wall_seconds\": ") + bad + ", \"b\": 2}");
    EXPECT_NE(error.find("\"wall_seconds\""), std::string::npos) << error;
    EXPECT_NE(error.find("not a finite number"), std::string::npos) << error;
  }
  // A number that overflows a double is as bad.
  EXPECT_NE(validate("{\"tend\": 1e400}").find("overflows"), std::string::npos);
  // Nested: the key is the innermost one.
  EXPECT_NE(validate("{\"parameters\": {\"E\": 1, \"Tinit\": nan}}").find("\"Tinit\""), std::string::npos);
}

TEST(JsonValidate, RefusesBrokenSyntaxSayingWhere) {
  EXPECT_NE(validate("{\"mesh\": \"a\"b\"}"), "");            // an unescaped quote
  EXPECT_NE(validate("{\"a\": 1,}"), "");                      // a trailing comma
  EXPECT_NE(validate("{\"a\": 1"), "");                        // cut short (a full disk)
  EXPECT_NE(validate(""), "");                                 // empty file
  EXPECT_NE(validate("{\"a\": 01}"), "");                      // leading zero
  EXPECT_NE(validate("{\"a\": \"line\nbreak\"}"), "");         // raw newline in a string
  EXPECT_NE(validate("{\"a\": 1} {}"), "");                    // two documents
  const std::string error = validate("{\n\"a\": 1,\n\"b\": x\n}");
  EXPECT_NE(error.find("line 3"), std::string::npos) << error;
}

TEST(JsonValidate, RoundTripsEveryFiniteDoubleAtTheScenesPrecision) {
  // The scenes print reals with precision 12 (and 17): any such text is a valid JSON number.
  for (double v : {0.0, -0.0, 1e-300, 5e-324, 1.7976931348623157e308, -123.456, 16931933.444}) {
    for (int precision : {12, 17}) {
      std::ostringstream text;
      text.precision(precision);
      text << "{\"v\": " << v << "}";
      EXPECT_EQ(validate(text.str()), "") << text.str();
    }
  }
}
