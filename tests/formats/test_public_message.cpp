// publicMessage, the one sanitiser of what the service and the report show: server paths become file
// names (the API's own paths stay), values and words are cut at about 40 characters, whole UTF-8
// characters kept, control characters gone.
#include <gtest/gtest.h>

#include "PublicMessage.h"

namespace lenslab {
namespace {

TEST(PublicMessage, ServerPathsBecomeFileNames) {
    EXPECT_EQ(publicMessage("/srv/lenslab/data/lenses/upload-0123456789abcdef.dat:3: column 2 (gap) is not a number"),
              "upload-0123456789abcdef.dat:3: column 2 (gap) is not a number");
    EXPECT_EQ(publicMessage("lens table '/tmp/x/data/lenses/upload-1.dat' not found"), "lens table 'upload-1.dat' not found");
    EXPECT_EQ(publicMessage("cannot open (/var/lib/lenslab/renders/): denied"), "cannot open (renders): denied");
    EXPECT_EQ(publicMessage("scene \"/home/u/scenes/cornell.pbrt\", line 5"), "scene \"cornell.pbrt\", line 5");
}

TEST(PublicMessage, TheServicesOwnPathsAndOtherSlashesStay) {
    const std::string kept[] = {
        "delete finished renders (DELETE /api/renders/{id}) or uploaded lenses (DELETE /api/lenses/{id})",
        "open http://127.0.0.1:8080/report/ when it is done", "f/64 is the narrowest", "see /report/index.html",
        "the root / is not a lens"};
    for (const std::string& text : kept) EXPECT_EQ(publicMessage(text), text);
}

TEST(PublicMessage, LongValuesAndWordsAreCutAtFortyCharacters) {
    const std::string value(500000, 'x');
    const std::string cut = publicMessage("WAVM value 2 is not a finite number: '" + value + "'");
    EXPECT_EQ(cut, "WAVM value 2 is not a finite number: '" + std::string(40, 'x') + "\u2026'");
    EXPECT_EQ(publicMessage("negative thickness -1" + std::string(62, '0') + " where"),
              "negative thickness -1" + std::string(38, '0') + "\u2026 where");
    // A quoted value with spaces is one value: cut as a whole, up to its closing quote.
    EXPECT_EQ(publicMessage("unknown glass 'a b c d e f g h i j k l m n o p q r s t u v w x y z' (searched)"),
              "unknown glass 'a b c d e f g h i j k l m n o p q r s t \u2026' (searched)");
    // An apostrophe inside a word opens no quote.
    EXPECT_EQ(publicMessage("the lens's widest f-number is f/2.02; the scene's f/1.4 is wider"),
              "the lens's widest f-number is f/2.02; the scene's f/1.4 is wider");
    // Cut at a character's boundary: 41 two-byte characters leave 40 and the mark.
    std::string greek;
    for (int i = 0; i < 41; ++i) greek += "\u03bb";
    std::string forty;
    for (int i = 0; i < 40; ++i) forty += "\u03bb";
    EXPECT_EQ(publicMessage("'" + greek + "'"), "'" + forty + "\u2026'");
    // However many short words it quotes, a message stays short.
    std::string words;
    for (int i = 0; i < 100000; ++i) words += "ab ";
    EXPECT_LE(publicMessage(words).size(), 1003u);
}

TEST(PublicMessage, ControlCharactersBecomeSpaces) {
    EXPECT_EQ(publicMessage("a\nb\rc\td\x1b" "e"), "a b c d e");
}

}  // namespace
}  // namespace lenslab
