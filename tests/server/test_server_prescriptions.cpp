// Real prescriptions through the service: the bundled .zmx lenses are listed with their glasses,
// aspheres and mirrors; a wavelength moves the lens data and the diagram (each its own cache entry);
// colour fans are their own diagram; a UTF-16 .zmx uploads; bad values are 4xx naming the parameter.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "FileText.h"
#include "RawConnection.h"
#include "ServerProcess.h"

using namespace lenslab::test;
using nlohmann::json;

namespace {

class ServerPrescriptions : public ::testing::Test {
protected:
    void SetUp() override { server_ = std::make_unique<ServerProcess>(binaryUnderTest(), data_.path() + "/data"); }
    TempDir data_;
    std::unique_ptr<ServerProcess> server_;
};

// UTF-16 LE with a byte order mark, as OpticStudio saves (the text is ASCII).
std::string utf16(const std::string& ascii) {
    std::string out = "\xff\xfe";
    for (char c : ascii) out += std::string{c, '\0'};
    return out;
}

}  // namespace

TEST_F(ServerPrescriptions, BundledZemaxLensesAreListedWithTheirSurfaces) {
    auto c = server_->client();
    const Reply list = get(c, "/api/lenses");
    ASSERT_EQ(list.status, 200);
    bool reflex = false;
    for (const auto& l : list.body["lenses"]) reflex = reflex || l["id"] == "us4666259-ex1-reflex-500mm";
    EXPECT_TRUE(reflex);
    const Reply lens = get(c, "/api/lenses/us4666259-ex1-reflex-500mm");
    ASSERT_EQ(lens.status, 200) << lens.raw;
    EXPECT_EQ(lens.body["format"], "zmx");
    EXPECT_NEAR(lens.body["efl"].get<double>(), 499.482, 0.005);  // the patent's f
    int mirrors = 0;
    double obscuration = 0;
    for (const auto& s : lens.body["surfaces"]) {
        mirrors += s["mirror"].get<bool>();
        if (s.contains("obscuration_diameter")) obscuration = s["obscuration_diameter"];
    }
    EXPECT_EQ(mirrors, 2);
    EXPECT_DOUBLE_EQ(obscuration, 38);
    const Reply sony = get(c, "/api/lenses/us2015-0092100-ex1-55mm");
    ASSERT_EQ(sony.status, 200);
    const json& first = sony.body["surfaces"][0];
    EXPECT_EQ(first["glass"], "model 1.58144/40.9");
    EXPECT_NEAR(first["nd"].get<double>(), 1.58144, 1e-9);
    EXPECT_NEAR(first["vd"].get<double>(), 40.9, 1e-6);
    int aspheres = 0;
    for (const auto& s : sony.body["surfaces"])
        for (const auto& a : s["aspheric"]) aspheres += a.get<double>() != 0 ? 1 : 0;
    EXPECT_GT(aspheres, 5);
}

TEST_F(ServerPrescriptions, WavelengthMovesTheLensDataAndTheDiagram) {
    auto c = server_->client();
    const Reply d = get(c, "/api/lenses/ac254-100-a?fstop=5");
    const Reply f = get(c, "/api/lenses/ac254-100-a?fstop=5&wavelength=486.1327");
    ASSERT_EQ(d.status, 200);
    ASSERT_EQ(f.status, 200) << f.raw;
    EXPECT_DOUBLE_EQ(d.body["wavelength_nm"].get<double>(), 587.5618);
    EXPECT_DOUBLE_EQ(f.body["wavelength_nm"].get<double>(), 486.1327);
    EXPECT_NEAR(f.body["efl"].get<double>(), d.body["chromatic"]["efl_F"].get<double>(), 1e-9);
    EXPECT_GT(std::fabs(f.body["efl"].get<double>() - d.body["efl"].get<double>()), 0.01);

    const std::string base = "/api/lenses/ac254-100-a/diagram.png?fstop=5&size=600x300";
    const auto atD = c.Get(base), atF = c.Get(base + "&wavelength=486.1327"), colour = c.Get(base + "&colour=1");
    ASSERT_EQ(atD->status, 200);
    ASSERT_EQ(atF->status, 200);
    ASSERT_EQ(colour->status, 200);
    EXPECT_NE(atD->body, atF->body);    // a cache keyed without the wavelength would serve d's picture
    EXPECT_NE(atD->body, colour->body);
    EXPECT_EQ(c.Get(base + "&wavelength=486.1327")->body, atF->body);
}

TEST_F(ServerPrescriptions, BadWavelengthAndColourAreRefusedNamingTheParameter) {
    auto c = server_->client();
    const Reply far = get(c, "/api/lenses/ac254-100-a?wavelength=3000");
    EXPECT_EQ(far.status, 422);
    EXPECT_EQ(far.body["error"], "query parameter wavelength: wavelength 3000 nm lies outside 180-2500 nm");
    EXPECT_EQ(get(c, "/api/lenses/ac254-100-a?wavelength=blue").status, 400);
    EXPECT_EQ(get(c, "/api/lenses/ac254-100-a/diagram.png?colour=2").status, 400);
    EXPECT_EQ(get(c, "/api/lenses/ac254-100-a/diagram.png?wavelength=150").status, 422);
}

TEST_F(ServerPrescriptions, Utf16ZemaxUploadReadsLikeTheFile) {
    auto c = server_->client();
    const std::string zmx = readFile(std::string(LENSLAB_SOURCE_DIR) + "/lenses/us2010-0033848-ex1-35mm.zmx");
    httplib::MultipartFormDataItems items = {{"file", utf16(zmx), "canon-35.zmx", "application/octet-stream"}};
    const auto uploaded = c.Post("/api/lenses", items);
    ASSERT_EQ(uploaded->status, 201) << uploaded->body;
    const std::string id = json::parse(uploaded->body)["id"];
    const Reply lens = get(c, "/api/lenses/" + id);
    ASSERT_EQ(lens.status, 200);
    EXPECT_EQ(lens.body["format"], "zmx");
    EXPECT_NEAR(lens.body["efl"].get<double>(), 34.59, 0.005);  // US 2010/0033848 Example 1's f
    // A broken one is a 4xx naming the file's line.
    const auto bad = c.Post("/api/lenses", httplib::MultipartFormDataItems{{"file", "VERS 1\nMODE SEQ\nSURF 0\n  TYPE COORDBRK\n", "bad.zmx", "text/plain"}});
    EXPECT_EQ(bad->status, 400);
    EXPECT_NE(bad->body.find("bad.zmx:4"), std::string::npos) << bad->body;
}

// A Code V lens whose plate is tilted 10 degrees by returning decentres, with a field list and EPD:
// what the editor's JSON must keep.
const char* const kTiltedPlateSeq = "RDM\nLEN \"A plate tilted 10 degrees before a singlet\"\nDIM M\nWL 587.5618\nEPD 10\n"
                                    "YAN 0 3\nSO 0 1e10\nS 0 4 N-BK7_SCHOTT\n  DAR\n  ADE 10\nS 0 5\n  DAR\n  ADE 10\n"
                                    "S 50 5 N-BK7_SCHOTT\nSTO\nS -50 45\nSI 0 0\nGO\n";

// The stored lens's JSON posted back unchanged writes the stored lens's own .zmx (tilts, fields and
// EPD kept), and the .dat refuses it as the stored lens's does; edited, the tilt stays.
TEST_F(ServerPrescriptions, AStoredLensPostedBackWritesItsOwnFile) {
    auto c = server_->client();
    const auto upload = c.Post("/api/lenses?name=tilted-plate.seq", kTiltedPlateSeq, "text/plain");
    ASSERT_TRUE(upload && upload->status == 201) << (upload ? upload->body : "no answer");
    const std::string id = json::parse(upload->body)["id"];
    const Reply stored = get(c, "/api/lenses/" + id + "/prescription.zmx");
    ASSERT_EQ(stored.status, 200) << stored.raw;
    const Reply rows = get(c, "/api/lenses/" + id + "/prescription");
    ASSERT_EQ(rows.status, 200);
    EXPECT_EQ(rows.body["rows"][0]["frame"]["tilt_degrees"], json({10, 0, 0}));
    EXPECT_EQ(rows.body["fields"]["points"][1]["y"], 3);
    EXPECT_EQ(rows.body["entrance_pupil_diameter"], 10);
    const Reply edited = postJson(c, "/api/prescriptions/prescription.zmx", rows.body);
    ASSERT_EQ(edited.status, 200) << edited.raw;
    EXPECT_EQ(edited.raw, stored.raw);
    EXPECT_NE(stored.raw.find("  SCBD 1 0 0 0 0 10 0 0\n"), std::string::npos) << stored.raw;
    EXPECT_NE(stored.raw.find("\nYFLN 0 3 0"), std::string::npos) << stored.raw;
    EXPECT_NE(stored.raw.find("\nENPD 10\n"), std::string::npos) << stored.raw;
    const Reply dat = postJson(c, "/api/prescriptions/table.dat", rows.body);
    EXPECT_EQ(dat.status, 422);
    EXPECT_EQ(dat.body["problem"], get(c, "/api/lenses/" + id + "/table.dat").body["problem"]);

    json radius = rows.body;
    radius["rows"][2]["radius"] = 48;
    const Reply changed = postJson(c, "/api/prescriptions/prescription.zmx", radius);
    ASSERT_EQ(changed.status, 200) << changed.raw;
    EXPECT_NE(changed.raw.find("  CURV 0.020833333333333333\n"), std::string::npos) << changed.raw;
    EXPECT_NE(changed.raw.find("  SCBD 1 0 0 0 0 10 0 0\n"), std::string::npos) << changed.raw;
    const Reply preview = postJson(c, "/api/prescriptions/preview", radius);
    ASSERT_EQ(preview.status, 200) << preview.raw.substr(0, 300);
    EXPECT_EQ(preview.body["lens"]["surfaces"][0]["frame"]["tilt_degrees"], json({10, 0, 0}));
    EXPECT_EQ(preview.body["lens"]["design"]["fields"]["points"].size(), 2u);

    // As a Code V file: the stored lens's and the posted rows' .seq are one text, and it holds the
    // returning tilt, the field and the EPD.
    const Reply seq = get(c, "/api/lenses/" + id + "/prescription.seq");
    ASSERT_EQ(seq.status, 200) << seq.raw;
    EXPECT_EQ(postJson(c, "/api/prescriptions/prescription.seq", rows.body).raw, seq.raw);
    for (const char* line : {"\nEPD 10\n", "ADE 10", "DAR", "\nGO\n"}) EXPECT_NE(seq.raw.find(line), std::string::npos) << line << " in\n" << seq.raw;
}

// Issue 40, item 9: a Code V lens with a private glass (defined in the .seq itself) posted back
// as rows wrote a .zmx naming a glass no catalog holds, a file that did not open. It is refused
// with 422 naming the row and why, as the stored lens's own .zmx is; a catalog glass writes.
TEST_F(ServerPrescriptions, APrivateGlassIsRefusedForAZmxThatWouldNotReadBack) {
    auto c = server_->client();
    const std::string seq = "PRV\nPWL 656.3 587.6 486.1\n'G1' 1.510 1.515 1.522\nEND\n"
                            "so 0 1e10\ns 0.02 5 'G1'\nsto\ns -0.02 40\nsi 0 0\nepd 10; wl 587.6\n";
    const auto upload = c.Post("/api/lenses?name=private.seq", seq, "text/plain");
    ASSERT_TRUE(upload && upload->status == 201) << (upload ? upload->body : "no answer");
    const std::string id = json::parse(upload->body)["id"];
    EXPECT_EQ(get(c, "/api/lenses/" + id + "/prescription.zmx").status, 422);
    json rows = get(c, "/api/lenses/" + id + "/prescription").body;
    ASSERT_EQ(rows["rows"][0]["glass"], "G1");
    const Reply refused = postJson(c, "/api/prescriptions/prescription.zmx", rows);
    EXPECT_EQ(refused.status, 422) << refused.raw;
    EXPECT_EQ(refused.body["row"], 1);
    EXPECT_EQ(refused.body["problem"].get<std::string>().rfind("written to a .zmx, this lens would not read back: unknown glass 'G1'", 0), 0u)
        << refused.raw;
    rows["rows"][0]["glass"] = "N-BK7";
    const Reply written = postJson(c, "/api/prescriptions/prescription.zmx", rows);
    ASSERT_EQ(written.status, 200) << written.raw;
    EXPECT_NE(written.raw.find("  GLAS N-BK7 "), std::string::npos) << written.raw;
}

// A stored lens downloads under its display name (the file's name without the extension), UTF-8
// in filename* and an ASCII stand-in in filename; the bundled under their file's name.
TEST_F(ServerPrescriptions, DownloadsAreNamedByTheLensesDisplayName) {
    auto c = server_->client();
    const auto upload = c.Post("/api/lenses?name=Objektiv%20%C3%B8%2050.seq", kTiltedPlateSeq, "text/plain");
    ASSERT_TRUE(upload && upload->status == 201) << (upload ? upload->body : "no answer");
    const std::string id = json::parse(upload->body)["id"];
    // On the wire: httplib's client percent-decodes the header values it reads.
    const auto disposition = [&](const std::string& path) {
        RawConnection connection(server_->port());
        connection.send("GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
        const std::string reply = connection.readReply(10);
        const std::size_t at = reply.find("Content-Disposition: ");
        return at == std::string::npos ? reply.substr(0, 300) : reply.substr(at + 21, reply.find("\r\n", at) - at - 21);
    };
    EXPECT_EQ(disposition("/api/lenses/" + id + "/prescription.zmx"),
              "attachment; filename=\"Objektiv _ 50.zmx\"; filename*=UTF-8''Objektiv%20%C3%B8%2050.zmx");
    EXPECT_EQ(disposition("/api/lenses/dgauss.50mm/table.dat"),
              "attachment; filename=\"dgauss.50mm.dat\"; filename*=UTF-8''dgauss.50mm.dat");
}

// Issue 40, finding 4: a stored lens written out (its rows, its .zmx) is read and written once and
// shared by readers asking at once and after, byte for byte (32 readers of a 1 MB Code V upload
// each read it again: 611 MB).
TEST_F(ServerPrescriptions, ConcurrentReadersOfAStoredLensShareOneWriting) {
    auto c = server_->client();
    const auto upload = c.Post("/api/lenses?name=tilted-plate.seq", kTiltedPlateSeq, "text/plain");
    ASSERT_TRUE(upload && upload->status == 201) << (upload ? upload->body : "no answer");
    const std::string id = json::parse(upload->body)["id"];
    const auto misses = [&] { return get(c, "/api/health").body["analysis_cache"]["misses"].get<int>(); };
    for (const std::string format : {"prescription", "prescription.zmx"}) {
        const int before = misses();
        const ConcurrentReads first = readAtOnce(*server_, "/api/lenses/" + id + "/" + format, 8);
        EXPECT_EQ(first.unexpected, 0) << format;
        EXPECT_GE(first.answered, 1) << format;
        const ConcurrentReads again = readAtOnce(*server_, "/api/lenses/" + id + "/" + format, 8);
        EXPECT_EQ(again.answered, 8) << format;
        EXPECT_EQ(misses() - before, 1) << format;
        ASSERT_EQ(again.bodies.size(), 1u) << format;
        EXPECT_EQ(first.bodies, again.bodies) << format;
    }
}
