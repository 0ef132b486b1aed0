// The well-formedness checker must catch what it is there to catch.
#include <gtest/gtest.h>

#include "HtmlCheck.h"

using lenslab::test::checkHtml;

TEST(HtmlCheck, AcceptsAWellFormedPage) {
    const auto r = checkHtml(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>a &amp; b</title></head>"
        "<body><p id=\"x\">text<br><img src=\"a.png\" alt=\"\"></p><svg><path d=\"M0 0\"/></svg>"
        "<!-- <p> in a comment --></body></html>");
    EXPECT_TRUE(r.errors.empty()) << r.errors.front();
    EXPECT_EQ(r.elements.size(), 10u);  // html head meta title body p br img svg path
}

TEST(HtmlCheck, CatchesUnclosedMismatchedAndStrayTags) {
    EXPECT_FALSE(checkHtml("<div><p>x</div>").errors.empty());   // mismatched
    EXPECT_FALSE(checkHtml("<main><section>").errors.empty());    // never closed
    EXPECT_FALSE(checkHtml("<p>x</p></div>").errors.empty());      // closes nothing
    EXPECT_FALSE(checkHtml("<img src=\"a.png>").errors.empty());   // unterminated attribute
}

TEST(HtmlCheck, CatchesBareAmpersandsDuplicateIdsAndAttributes) {
    EXPECT_FALSE(checkHtml("<p>fish & chips</p>").errors.empty());
    EXPECT_FALSE(checkHtml("<p id=\"a\"></p><p id=\"a\"></p>").errors.empty());
    EXPECT_FALSE(checkHtml("<p class=\"a\" class=\"b\"></p>").errors.empty());
    EXPECT_FALSE(checkHtml("<p>1 < 2</p>").errors.empty());
}
