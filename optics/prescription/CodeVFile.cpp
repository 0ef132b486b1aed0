#include "prescription/CodeVFile.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <optional>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "prescription/Medium.h"
#include "prescription/NumberText.h"
#include "prescription/TextEncoding.h"
#include "prescription/Wavelength.h"

namespace lenslab {

namespace {

// One command as the file gives it: its name (upper case) and the words after it. Quoted strings
// are one word, quotes removed, `quoted` set.
struct Word {
    std::string text;
    bool quoted = false;
};
struct Command {
    int line = 0;
    std::string name;
    std::vector<Word> words;
};

// Lines joined at a trailing '&', comments ('!' outside quotes) dropped, commands split at ';'.
std::vector<Command> splitCommands(const std::string& text, const std::string& name) {
    std::vector<Command> commands;
    std::istringstream in(text);
    std::string pending;
    int pendingLine = 0, lineNo = 0;
    auto flush = [&](const std::string& body, int line) {
        std::vector<Word> words;
        Word current;
        bool inWord = false;
        auto end = [&] {
            if (!inWord) return;
            if (!current.quoted && current.text == ";") {
            } else {
                words.push_back(current);
            }
            current = Word{};
            inWord = false;
        };
        auto command = [&] {
            end();
            if (words.empty()) return;
            Command c;
            c.line = line;
            c.name = upperCase(words.front().text);
            c.words.assign(words.begin() + 1, words.end());
            if (words.front().quoted) c.name = "'" + words.front().text + "'";  // a private glass's row
            commands.push_back(c);
            words.clear();
        };
        for (std::size_t i = 0; i < body.size(); ++i) {
            const char c = body[i];
            if ((c == '\'' || c == '"') && !inWord) {
                const std::size_t close = body.find(c, i + 1);
                if (close == std::string::npos) throw LensTableError(name, line, "a quoted string is not closed");
                current.text = body.substr(i + 1, close - i - 1);
                current.quoted = true;
                inWord = true;
                end();
                i = close;
            } else if (c == ';') {
                command();
            } else if (std::isspace(static_cast<unsigned char>(c))) {
                end();
            } else {
                current.text += c;
                inWord = true;
                // A qualifier with a quoted label (CIR OBS L'A' 0.38) keeps its quotes inside the word.
                if (c == '\'' || c == '"') {
                    const std::size_t close = body.find(c, i + 1);
                    if (close == std::string::npos) throw LensTableError(name, line, "a quoted string is not closed");
                    current.text += body.substr(i + 1, close - i);
                    i = close;
                }
            }
        }
        command();
    };
    for (std::string raw; std::getline(in, raw);) {
        ++lineNo;
        if (!raw.empty() && raw.back() == '\r') raw.pop_back();
        // Drop the comment: '!' outside quotes.
        char quote = 0;
        std::size_t cut = raw.size();
        for (std::size_t i = 0; i < raw.size(); ++i) {
            if (quote) {
                if (raw[i] == quote) quote = 0;
            } else if (raw[i] == '\'' || raw[i] == '"') {
                if (i == 0 || std::isspace(static_cast<unsigned char>(raw[i - 1])) || raw[i - 1] == ';') quote = raw[i];
            } else if (raw[i] == '!') {
                cut = i;
                break;
            }
        }
        std::string body = raw.substr(0, cut);
        while (!body.empty() && std::isspace(static_cast<unsigned char>(body.back()))) body.pop_back();
        if (pending.empty()) pendingLine = lineNo;
        if (!body.empty() && body.back() == '&') {
            body.pop_back();
            pending += body + " ";
            continue;
        }
        pending += body;
        flush(pending, pendingLine);
        pending.clear();
    }
    if (!pending.empty()) flush(pending, pendingLine);
    return commands;
}

// A surface as the file gives it, in lens units (DIM may come anywhere).
struct RawSurface {
    int line = 0;
    double shape = 0;        // radius or curvature, as read
    bool curvatureGiven = false;
    double thickness = 0;
    std::string glass, catalog;
    std::optional<std::array<double, 2>> fictitious;  // nd, Vd of a glass given by its figures
    bool mirror = false;
    bool stop = false;
    double conic = 0;
    std::array<double, 10> polynomial{};  // A .. J: r^4 .. r^22
    std::string name;
    std::optional<FrameChange> frame;
    // Apertures: the clear one and an obscuration, each a shape in lens units (half widths).
    std::optional<SurfaceAperture> clear, obscuration;
    SurfaceAperture* lastAperture = nullptr;  // the one ADX/ADY move
};

struct FieldLists {
    std::vector<double> x, y, weights;
    std::optional<FieldType> type;
};

constexpr double kInfiniteObject = 1e10;  // Code V writes 1e10 and more for an object at infinity
constexpr int kMaxWavelengths = 24;
constexpr int kMaxFields = 100;

struct SeqReader {
    std::string name;
    double millimetresPerUnit = 1;
    bool radiusMode = false;  // RDM: radii; without it (as ray-optics reads these files) curvatures
    LensTable t;
    RawSurface object, image;
    bool haveObject = false, haveImage = false;
    bool closed = false;  // GO read: the file's last line, so nothing after it was lost
    std::vector<RawSurface> surfaces;
    RawSurface* current = nullptr;
    std::vector<double> wavelengths, weights;
    int reference = 0, referenceLine = 0;
    FieldLists fields;
    int fieldLine = 0;
    // Private catalog (PRV ... END).
    bool inPrivate = false;
    std::vector<double> privateWavelengths;
    std::optional<double> epd, fno, nao, imageNa;

    [[noreturn]] void fail(int line, const std::string& problem) const { throw LensTableError(name, line, problem); }

    double number(const Command& c, std::size_t i) const {
        if (i >= c.words.size())
            fail(c.line, c.name + " needs at least " + std::to_string(i + 1) + " value(s) after it");
        const std::string& f = c.words[i].text;
        char* end = nullptr;
        errno = 0;
        const double v = std::strtod(f.c_str(), &end);
        if (end == f.c_str() || *end != '\0' || !std::isfinite(v))
            fail(c.line, c.name + " value " + std::to_string(i + 1) + " is not a finite number: '" + f.substr(0, 40) + "'");
        return v;
    }

    std::vector<double> numbers(const Command& c, std::size_t limit) const {
        if (c.words.size() > limit) fail(c.line, c.name + " lists more than " + std::to_string(limit) + " values");
        std::vector<double> v;
        for (std::size_t i = 0; i < c.words.size(); ++i) v.push_back(number(c, i));
        if (v.empty()) fail(c.line, c.name + " needs at least one value after it");
        return v;
    }

    RawSurface& surface(const Command& c) {
        if (!current) fail(c.line, c.name + " before the first surface (SO or S): it describes a surface");
        return *current;
    }
    RawSurface& lensSurface(const Command& c) {
        RawSurface& s = surface(c);
        if (&s == &object || &s == &image)
            fail(c.line, c.name + " on the " + (&s == &object ? "object" : "image") + " surface: it needs a lens surface");
        return s;
    }
};

// ---- system data -------------------------------------------------------------------------------

void readDim(SeqReader& r, const Command& c) {
    if (c.words.empty()) r.fail(c.line, "DIM needs a unit: M, C or I");
    const std::string unit = upperCase(c.words[0].text);
    static const std::unordered_map<std::string, double> units = {{"M", 1}, {"MM", 1}, {"C", 10}, {"CM", 10},
                                                                  {"I", 25.4}, {"IN", 25.4}};
    const auto it = units.find(unit);
    if (it == units.end()) r.fail(c.line, "DIM " + c.words[0].text + " is not one of M, C, I (millimetres, centimetres, inches)");
    r.millimetresPerUnit = it->second;
}

void readRdm(SeqReader& r, const Command& c) {
    r.radiusMode = c.words.empty() || upperCase(c.words[0].text)[0] != 'N';
}

void readTitle(SeqReader& r, const Command& c) {
    std::string title;
    for (const Word& w : c.words) title += (title.empty() ? "" : " ") + w.text;
    if (!title.empty()) r.t.comments.push_back(title);
}

void readWl(SeqReader& r, const Command& c) {
    r.wavelengths = r.numbers(c, kMaxWavelengths);
    for (double nm : r.wavelengths)
        if (const auto problem = wavelengthProblem(nm)) r.fail(c.line, "WL: " + *problem);
}

void readWtw(SeqReader& r, const Command& c) { r.weights = r.numbers(c, kMaxWavelengths); }

void readRef(SeqReader& r, const Command& c) {
    const double v = r.number(c, 0);
    if (v != std::floor(v) || v < 1 || v > kMaxWavelengths)
        r.fail(c.line, "REF names a wavelength by its number (1.." + std::to_string(kMaxWavelengths) + "), found " +
                           c.words[0].text);
    r.reference = static_cast<int>(v);
    r.referenceLine = c.line;
}

// XAN/YAN, XOB/YOB, XIM/YIM, XRI/YRI: one coordinate of every field; the type from the letters.
void readField(SeqReader& r, const Command& c) {
    static const std::unordered_map<std::string, FieldType> types = {
        {"AN", FieldType::ObjectAngle}, {"OB", FieldType::ObjectHeight},
        {"IM", FieldType::ParaxialImageHeight}, {"RI", FieldType::RealImageHeight}};
    const FieldType type = types.at(c.name.substr(1));
    if (r.fields.type && *r.fields.type != type)
        r.fail(c.line, c.name + " gives " + fieldTypeName(type) + "s after the file gave " + fieldTypeName(*r.fields.type) +
                           "s: one kind of field per file");
    r.fields.type = type;
    (c.name[0] == 'X' ? r.fields.x : r.fields.y) = r.numbers(c, kMaxFields);
    r.fieldLine = c.line;
}

void readWtf(SeqReader& r, const Command& c) { r.fields.weights = r.numbers(c, kMaxFields); }

void readEpd(SeqReader& r, const Command& c) {
    r.epd = r.number(c, 0);
    if (!(*r.epd > 0)) r.fail(c.line, "EPD must be a positive diameter");
}
void readFno(SeqReader& r, const Command& c) {
    r.fno = r.number(c, 0);
    if (!(*r.fno > 0)) r.fail(c.line, "FNO must be positive");
}
void readNao(SeqReader& r, const Command& c) {
    r.nao = r.number(c, 0);
    if (!(*r.nao > 0 && *r.nao < 1)) r.fail(c.line, "NAO must lie between 0 and 1");
}
void readNa(SeqReader& r, const Command& c) {
    r.imageNa = r.number(c, 0);
    if (!(*r.imageNa > 0 && *r.imageNa < 1)) r.fail(c.line, "NA must lie between 0 and 1");
}

// ---- private catalog: PRV, PWL wavelengths, 'NAME' indices or 'NAME' LAU coefficients, END --------

void readPrv(SeqReader& r, const Command&) { r.inPrivate = true; }
void readPwl(SeqReader& r, const Command& c) { r.privateWavelengths = r.numbers(c, 100); }
void readEnd(SeqReader& r, const Command&) { r.inPrivate = false; }

void readPrivateGlass(SeqReader& r, const Command& c) {
    const std::string glass = c.name.substr(1, c.name.size() - 2);
    if (!r.inPrivate) r.fail(c.line, "'" + glass + "': a quoted glass definition belongs between PRV and END");
    GlassSubstitute s;
    s.name = glass;
    s.source = r.name + ":" + std::to_string(c.line);
    try {
        if (!c.words.empty() && upperCase(c.words[0].text) == "LAU") {
            // Laurent: n^2 = A0 + A1 L^2 + A2 L^-2 + A3 L^-4 + A4 L^-6 + A5 L^-8 (L in micrometres).
            Command values = c;
            values.words.erase(values.words.begin());
            const std::vector<double> a = r.numbers(values, 6);
            Medium m;
            m.name = glass;
            m.catalog = "private";
            m.formula = DispersionFormula::SchottPolynomial;
            m.coefficients[0] = a[0];
            if (a.size() > 1) m.coefficients[1] = a[1];
            for (std::size_t i = 2; i < a.size(); ++i) m.coefficients[i + 1] = a[i];
            m.nd = refractiveIndex(m, kWavelengthD);
            m.vd = abbeNumber(m);
            s.medium = m;
        } else {
            const std::vector<double> n = r.numbers(c, 100);
            if (n.size() != r.privateWavelengths.size())
                r.fail(c.line, "'" + glass + "' lists " + std::to_string(n.size()) + " indices for the " +
                                   std::to_string(r.privateWavelengths.size()) + " wavelengths of PWL");
            std::vector<std::array<double, 2>> pairs;
            for (std::size_t i = 0; i < n.size(); ++i) pairs.push_back({r.privateWavelengths[i], n[i]});
            Medium m = tabulatedMedium(glass, pairs);
            m.catalog = "private";
            s.medium = m;
        }
    } catch (const std::invalid_argument& e) {
        r.fail(c.line, e.what());
    }
    r.t.substitutes.push_back(s);
}

// ---- surfaces ----------------------------------------------------------------------------------

// The glass word(s) after S r t: REFL, AIR, a fictitious glass (n,v / n:v / a glass code such as
// 589613 or 517000.520000), a catalog glass (NBK7_SCHOTT, or BK7 followed by its catalog).
// Digits with at most one point in them: a glass code (589613, 517000.520000), nothing else that
// strtod would read (signs, exponents, hexadecimal, inf).
bool isGlassCode(const std::string& text) {
    const auto point = text.find('.');
    const auto isDigit = [](char ch) { return ch >= '0' && ch <= '9'; };
    return !text.empty() && point != 0 && std::all_of(text.begin(), text.begin() + std::min(point, text.size()), isDigit) &&
           (point == std::string::npos ||
            (point + 1 < text.size() && std::all_of(text.begin() + point + 1, text.end(), isDigit)));
}

// The value of a glass code's digits (strtod: a thousand digits overflow to inf and are refused by
// the caller's check rather than thrown).
double decimal(const std::string& digits) { return std::strtod(digits.c_str(), nullptr); }

void readGlass(SeqReader& r, RawSurface& s, const Command& c, std::size_t from) {
    if (from >= c.words.size()) return;
    const Word& w = c.words[from];
    const std::string u = upperCase(w.text);
    if (c.words.size() > from + 2) r.fail(c.line, c.name + " has more words than a radius, a thickness and a glass");
    if (!w.quoted && u == "REFL") {
        s.mirror = true;
        return;
    }
    if (!w.quoted && u == "AIR") return;
    if (w.quoted) {
        s.glass = w.text;  // a private catalog's
        return;
    }
    for (const char separator : {',', ':'}) {
        const auto at = w.text.find(separator);
        if (at == std::string::npos) continue;
        const Command parts{c.line, c.name, {{w.text.substr(0, at)}, {w.text.substr(at + 1)}}};
        const double nd = r.number(parts, 0), vd = r.number(parts, 1);
        if (!(nd > 1 && vd > 0)) r.fail(c.line, "fictitious glass " + w.text + ": nd must exceed 1 and Vd be positive");
        s.fictitious = std::array<double, 2>{nd, vd};
        return;
    }
    if (isGlassCode(w.text)) {
        // A glass code: the digits before the point are nd - 1 (517 or 517000: 1.517), those after it
        // a tenth of Vd (520000: 52.0); six digits without a point split three and three (589613).
        const auto point = w.text.find('.');
        const std::string digits = w.text.substr(0, point);
        const double code = decimal(w.text);
        double nd = 0, vd = 0;
        if (point == std::string::npos && digits.size() == 6) {
            nd = 1 + decimal(digits.substr(0, 3)) / 1000;
            vd = decimal(digits.substr(3)) / 10;
        } else if (code >= 1) {
            // The fraction from its own digits: code - floor(code) loses them to the whole part's.
            const double whole = std::floor(code);
            nd = 1 + whole / std::pow(10.0, std::floor(std::log10(whole)) + 1);
            vd = point == std::string::npos ? 0 : 100 * decimal("0" + w.text.substr(point));
        }
        if (!(nd > 1 && vd > 0)) r.fail(c.line, "glass code " + w.text + " is not nd and Vd (589613, 517000.520000)");
        s.fictitious = std::array<double, 2>{nd, vd};
        return;
    }
    const auto underscore = w.text.rfind('_');
    if (underscore != std::string::npos && underscore > 0) {
        s.glass = w.text.substr(0, underscore);
        s.catalog = w.text.substr(underscore + 1);
    } else {
        s.glass = w.text;
        if (c.words.size() > from + 1) s.catalog = c.words[from + 1].text;
    }
}

void startSurface(SeqReader& r, const Command& c, RawSurface& s) {
    s = RawSurface{};
    s.line = c.line;
    s.shape = r.number(c, 0);
    s.curvatureGiven = !r.radiusMode;
    if (c.words.size() > 1) s.thickness = r.number(c, 1);
    r.current = &s;
}

void readSo(SeqReader& r, const Command& c) {
    if (r.haveObject) r.fail(c.line, "a second object surface (SO)");
    if (!r.surfaces.empty()) r.fail(c.line, "SO after the first lens surface: the object surface comes first");
    startSurface(r, c, r.object);
    r.haveObject = true;
    if (c.words.size() > 2) r.fail(c.line, "SO takes a radius and a thickness; the object space is air");
}

void readS(SeqReader& r, const Command& c) {
    if (r.haveImage) r.fail(c.line, "S after the image surface (SI)");
    if (int(r.surfaces.size()) == kMaxLensSurfaces)
        r.fail(c.line, "too many surfaces: a lens may have at most " + std::to_string(kMaxLensSurfaces) + " surfaces");
    if (c.words.size() < 2) r.fail(c.line, "S needs a radius (or curvature) and a thickness");
    r.surfaces.emplace_back();
    startSurface(r, c, r.surfaces.back());
    readGlass(r, r.surfaces.back(), c, 2);
}

void readSi(SeqReader& r, const Command& c) {
    if (r.haveImage) r.fail(c.line, "a second image surface (SI)");
    startSurface(r, c, r.image);
    r.haveImage = true;
    if (r.image.shape != 0) r.fail(c.line, "a curved image surface (SI radius " + c.words[0].text + ") is not supported: the film is flat");
}

// STO marks the surface given last as the stop; values after it would be a surface written in a
// form Code V does not have (they used to be dropped without a word).
void readSto(SeqReader& r, const Command& c) {
    if (!c.words.empty()) r.fail(c.line, "STO takes no values (it marks the surface before it as the stop; give the surface with S)");
    r.lensSurface(c).stop = true;
}

void readRdy(SeqReader& r, const Command& c) {
    RawSurface& s = r.surface(c);
    s.shape = r.number(c, 0);
    s.curvatureGiven = false;
}

void readCuy(SeqReader& r, const Command& c) {
    // CUY with qualifiers is a solve; its value is already the surface's.
    if (!c.words.empty() && !std::isdigit(static_cast<unsigned char>(c.words[0].text[0])) && c.words[0].text[0] != '-' &&
        c.words[0].text[0] != '.')
        return;
    RawSurface& s = r.surface(c);
    s.shape = r.number(c, 0);
    s.curvatureGiven = true;
}

void readThi(SeqReader& r, const Command& c) {
    if (!c.words.empty() && std::isalpha(static_cast<unsigned char>(c.words[0].text[0]))) return;  // a solve (THI HMY 0)
    r.surface(c).thickness = r.number(c, 0);
}

void readSph(SeqReader& r, const Command& c) {
    RawSurface& s = r.lensSurface(c);
    s.conic = 0;
    s.polynomial = {};
}
void readConOrAsp(SeqReader& r, const Command& c) { r.lensSurface(c); }
void readK(SeqReader& r, const Command& c) { r.lensSurface(c).conic = r.number(c, 0); }

void readPolynomial(SeqReader& r, const Command& c) {
    static const std::string kLetters = "ABCDEFGHJ";
    r.lensSurface(c).polynomial[kLetters.find(c.name[0])] = r.number(c, 0);
}

void readSlb(SeqReader& r, const Command& c) {
    if (!c.words.empty()) r.surface(c).name = c.words[0].text;
}

// ---- decentres and tilts -----------------------------------------------------------------------

FrameChange& frameOf(SeqReader& r, const Command& c) {
    RawSurface& s = r.surface(c);
    if (&s == &r.object) r.fail(c.line, c.name + " on the object surface: decentre the first lens surface instead");
    if (!s.frame) s.frame = FrameChange{};
    return *s.frame;
}

void readDecentre(SeqReader& r, const Command& c) {
    FrameChange& f = frameOf(r, c);
    const int axis = c.name[0] - 'X';
    f.decentre[axis] = r.number(c, 0);
}

void readTilt(SeqReader& r, const Command& c) {
    FrameChange& f = frameOf(r, c);
    f.tiltDegrees[c.name[0] - 'A'] = r.number(c, 0);
}

void readFrameMode(SeqReader& r, const Command& c) {
    FrameChange& f = frameOf(r, c);
    f.mode = c.name == "DAR" ? FrameMode::DecentreAndReturn : c.name == "BEN" ? FrameMode::Bend : FrameMode::Reverse;
    if (&r.surface(c) == &r.image && f.mode != FrameMode::Basic)
        r.fail(c.line, c.name + " on the image surface: nothing follows it");
}

// ---- apertures ---------------------------------------------------------------------------------

// CIR, REX, REY, ELX, ELY with the qualifiers OBS (an obscuration), HOL (a hole: rays there are
// lost, as at an obscuration), EDG (the mechanical edge: drawn, not clipped), S and L'..' labels.
void readAperture(SeqReader& r, const Command& c) {
    RawSurface& s = r.surface(c);
    if (&s == &r.object) r.fail(c.line, c.name + " on the object surface");
    bool obscuration = false, edge = false;
    std::size_t i = 0;
    for (; i < c.words.size(); ++i) {
        const std::string q = upperCase(c.words[i].text);
        if (q == "OBS" || q == "HOL") obscuration = true;
        else if (q == "EDG") edge = true;
        else if (q.rfind("L'", 0) == 0 || q.rfind("L\"", 0) == 0 || q == "ALL") continue;
        else break;
    }
    Command values{c.line, c.name, {c.words.begin() + std::min(i, c.words.size()), c.words.end()}};
    const double size = r.number(values, 0);
    if (!(size > 0)) r.fail(c.line, c.name + " must be a positive semi-aperture, found " + values.words[0].text);
    if (edge || &s == &r.image) return;
    std::optional<SurfaceAperture>& slot = obscuration ? s.obscuration : s.clear;
    const ApertureKind kind = c.name == "CIR" ? ApertureKind::Circular : c.name[0] == 'R' ? ApertureKind::Rectangular
                                                                                          : ApertureKind::Elliptical;
    if (!slot || slot->kind != kind) {
        slot = SurfaceAperture{};
        slot->kind = kind;
        slot->halfWidthX = slot->halfWidthY = size;
    }
    if (kind == ApertureKind::Circular || c.name[2] == 'X') slot->halfWidthX = size;
    if (kind == ApertureKind::Circular || c.name[2] == 'Y') slot->halfWidthY = size;
    s.lastAperture = &*slot;
}

void readApertureDecentre(SeqReader& r, const Command& c) {
    RawSurface& s = r.surface(c);
    if (!s.lastAperture) r.fail(c.line, c.name + " before an aperture (CIR, REX/REY, ELX/ELY) on this surface");
    (c.name[2] == 'X' ? s.lastAperture->centreX : s.lastAperture->centreY) = r.number(c, 0);
}

void readApertureRotation(SeqReader& r, const Command& c) {
    if (r.number(c, 0) != 0) r.fail(c.line, "rotated apertures (ARO) are not supported: apertures keep the surface's x and y");
}

// ---- commands that change nothing lenslab computes ----------------------------------------------

void ignore(SeqReader&, const Command&) {}

void readGo(SeqReader& r, const Command&) { r.closed = true; }

// CUF is zero in every file seen; anything else would change the surface.
void readZeroOnly(SeqReader& r, const Command& c) {
    for (std::size_t i = 0; i < c.words.size(); ++i)
        if (std::isdigit(static_cast<unsigned char>(c.words[i].text[0])) || c.words[i].text[0] == '-' ||
            c.words[i].text[0] == '.')
            if (r.number(c, i) != 0) r.fail(c.line, c.name + " " + c.words[i].text + " is not supported (only 0)");
}

void refuse(SeqReader& r, const Command& c, const std::string& what) {
    r.fail(c.line, "command " + c.name + " (" + what + ") is not supported");
}

using Handler = std::function<void(SeqReader&, const Command&)>;

const std::unordered_map<std::string, Handler>& handlers() {
    static const std::unordered_map<std::string, Handler> table = [] {
        std::unordered_map<std::string, Handler> h = {
            {"LEN", ignore}, {"TIT", readTitle}, {"DIM", readDim}, {"RDM", readRdm}, {"WL", readWl},
            {"WTW", readWtw}, {"REF", readRef}, {"WTF", readWtf}, {"EPD", readEpd}, {"FNO", readFno},
            {"NAO", readNao}, {"NA", readNa}, {"SO", readSo}, {"S", readS}, {"SI", readSi}, {"STO", readSto},
            {"RDY", readRdy}, {"CUY", readCuy}, {"THI", readThi}, {"SPH", readSph}, {"CON", readConOrAsp},
            {"ASP", readConOrAsp}, {"K", readK}, {"SLB", readSlb}, {"PRV", readPrv}, {"PWL", readPwl},
            {"END", readEnd}, {"XDE", readDecentre}, {"YDE", readDecentre}, {"ZDE", readDecentre},
            {"ADE", readTilt}, {"BDE", readTilt}, {"CDE", readTilt}, {"DAR", readFrameMode},
            {"BEN", readFrameMode}, {"REV", readFrameMode}, {"CIR", readAperture}, {"REX", readAperture},
            {"REY", readAperture}, {"ELX", readAperture}, {"ELY", readAperture}, {"ADX", readApertureDecentre},
            {"ADY", readApertureDecentre}, {"ARO", readApertureRotation}, {"CUF", readZeroOnly}, {"GO", readGo},
            // Display, optimisation, tolerancing and bookkeeping: they change no surface.
            {"INI", ignore}, {"TEM", ignore}, {"PRE", ignore}, {"VUX", ignore}, {"VLX", ignore}, {"VUY", ignore},
            {"VLY", ignore}, {"CA", ignore}, {"POL", ignore}, {"PIM", ignore}, {"CLS", ignore}, {"PIK", ignore},
            {"DER", ignore}, {"WID", ignore}, {"CCY", ignore}, {"CCX", ignore}, {"THC", ignore}, {"THM", ignore},
            {"CUM", ignore}, {"KC", ignore}, {"AC", ignore}, {"BC", ignore}, {"CC", ignore}, {"DC", ignore},
            {"EC", ignore}, {"GLC", ignore}, {"CWL", ignore}, {"SPL", ignore},
        };
        for (const char* axis : {"XAN", "YAN", "XOB", "YOB", "XIM", "YIM", "XRI", "YRI"}) h[axis] = readField;
        for (const char* letter : {"A", "B", "C", "D", "E", "F", "G", "H", "J"}) h[letter] = readPolynomial;
        h["DIF"] = [](SeqReader& r, const Command& c) { refuse(r, c, "diffractive and holographic surfaces"); };
        for (const char* c : {"HOR", "HWL", "HCT", "HCO", "HCC", "HV1", "HV2", "HX1", "HY1", "HZ1"})
            h[c] = [](SeqReader& r, const Command& cmd) { refuse(r, cmd, "diffractive and holographic surfaces"); };
        for (const char* c : {"XTO", "YTO", "SPS", "XYP", "ZRN", "ZFR", "QBF", "QCN", "UDS", "SPT"})
            h[c] = [](SeqReader& r, const Command& cmd) { refuse(r, cmd, "this surface type"); };
        for (const char* c : {"GRN", "GRD", "GRM"})
            h[c] = [](SeqReader& r, const Command& cmd) { refuse(r, cmd, "gradient-index media"); };
        for (const char* c : {"ZOO", "POS", "SEL"})
            h[c] = [](SeqReader& r, const Command& cmd) { refuse(r, cmd, "zoom positions; lenslab reads one configuration"); };
        return h;
    }();
    return table;
}

// The command's handler name: Code V accepts commands spelled out (TITLE, STOP) by their first
// three letters; S, SO and SI stand alone.
std::string handlerName(const std::string& name) {
    if (name.size() > 3 && handlers().count(name.substr(0, 3))) return name.substr(0, 3);
    return name;
}

// ---- assembly ----------------------------------------------------------------------------------

LensTableRow lensRow(const SeqReader& r, const RawSurface& s, int number) {
    const double u = r.millimetresPerUnit;
    LensTableRow row;
    row.line = s.line;
    row.stop = s.stop;
    const double radius = s.curvatureGiven ? (s.shape == 0 ? 0 : 1 / s.shape) : s.shape;
    row.radius = radius * u;
    if (!std::isfinite(row.radius)) r.fail(s.line, "the radius of surface " + std::to_string(number) + " is not a finite number of mm");
    row.gap = s.thickness * u;
    row.mirror = s.mirror;
    if (!s.mirror && s.fictitious) {
        row.index = (*s.fictitious)[0];
        row.abbe = (*s.fictitious)[1];
    } else if (!s.mirror) {
        row.glass = s.glass;
        row.glassCatalog = s.catalog;
    }
    row.conic = s.conic;
    // A (r^4) .. G (r^16) are the table's terms 2 .. 8; H and J reach past them.
    for (int i = 0; i < 7; ++i) row.aspheric[i + 1] = s.polynomial[i] * std::pow(u, -3 - 2 * i);
    for (int i = 7; i < 9; ++i)
        if (s.polynomial[i] != 0)
            r.fail(s.line, std::string("aspheric term ") + "HJ"[i - 7] + " (r^" + std::to_string(4 + 2 * i) +
                               ") is not supported: even aspheres reach r^16 (A to G)");
    for (double a : row.aspheric)
        if (!std::isfinite(a)) r.fail(s.line, "an aspheric coefficient is not finite in millimetres");
    row.name = s.name;
    if (s.frame) {
        FrameChange f = *s.frame;
        for (double& d : f.decentre) d *= u;
        row.frame = f;
    }
    auto scaled = [&](SurfaceAperture a) {
        a.halfWidthX *= u, a.halfWidthY *= u, a.centreX *= u, a.centreY *= u;
        return a;
    };
    // A circle about the vertex is the table's diameter; any other shape travels as the shape, the
    // diameter the circle that holds it (as a .zmx's reads).
    if (s.clear) {
        const SurfaceAperture a = scaled(*s.clear);
        if (a.kind == ApertureKind::Circular && a.centreX == 0 && a.centreY == 0) row.diameter = 2 * a.halfWidthX;
        else row.clearShape = a, row.diameter = 2 * a.reach();
    } else {
        row.automaticDiameter = true;
    }
    if (s.obscuration) {
        const SurfaceAperture a = scaled(*s.obscuration);
        if (a.kind == ApertureKind::Circular && a.centreX == 0 && a.centreY == 0) row.obscurationDiameter = 2 * a.halfWidthX;
        else row.obscurationShape = a;
    }
    return row;
}

void setWavelengths(SeqReader& r) {
    LensTable& t = r.t;
    t.wavelengths = r.wavelengths;
    if (!r.weights.empty() && r.weights.size() != r.wavelengths.size())
        r.fail(0, "WTW lists " + std::to_string(r.weights.size()) + " weights for " + std::to_string(r.wavelengths.size()) +
                      " wavelengths");
    t.wavelengthWeights = r.weights.empty() ? std::vector<double>(t.wavelengths.size(), 1.0) : r.weights;
    if (t.wavelengths.empty()) return;
    const int ref = r.reference ? r.reference : 1;
    if (ref > int(t.wavelengths.size()))
        r.fail(r.referenceLine, "REF " + std::to_string(ref) + " names no WL wavelength (1.." +
                                    std::to_string(t.wavelengths.size()) + ")");
    t.primaryWavelength = t.wavelengths[ref - 1];
}

void setFields(SeqReader& r) {
    const FieldLists& f = r.fields;
    if (!f.type) return;
    const std::size_t n = std::max(f.x.size(), f.y.size());
    if ((!f.x.empty() && f.x.size() != n) || (!f.y.empty() && f.y.size() != n) || (!f.weights.empty() && f.weights.size() != n))
        r.fail(r.fieldLine, "the field lists differ in length (X " + std::to_string(f.x.size()) + ", Y " +
                                std::to_string(f.y.size()) + ", WTF " + std::to_string(f.weights.size()) + ")");
    const double u = *f.type == FieldType::ObjectAngle ? 1 : r.millimetresPerUnit;
    r.t.fields.type = *f.type;
    for (std::size_t i = 0; i < n; ++i)
        r.t.fields.points.push_back({f.x.empty() ? 0 : f.x[i] * u, f.y.empty() ? 0 : f.y[i] * u,
                                     f.weights.empty() ? 1 : f.weights[i]});
}

LensTable assemble(SeqReader& r, int lastLine) {
    if (r.surfaces.empty())
        r.fail(std::max(lastLine, 1), "no lens surfaces: a .seq needs S commands between the object (SO) and the image (SI)");
    LensTable& t = r.t;
    t.name = r.name;
    t.layout = TableLayout::GapAfter;
    t.format = "seq";
    const double u = r.millimetresPerUnit;
    // Code V's stop defaults to the first surface.
    if (std::none_of(r.surfaces.begin(), r.surfaces.end(), [](const RawSurface& s) { return s.stop; }))
        r.surfaces.front().stop = true;
    int stops = 0;
    for (const RawSurface& s : r.surfaces)
        if (s.stop && ++stops > 1) r.fail(s.line, "a second stop (STO)");
    for (std::size_t i = 0; i < r.surfaces.size(); ++i) {
        t.rows.push_back(lensRow(r, r.surfaces[i], int(i) + 1));
        // A mirror sends the ray back through the medium it came from: its row holds that medium,
        // as a .zmx's mirror row does.
        if (t.rows.back().mirror && i > 0) {
            LensTableRow &mirror = t.rows.back(), &before = t.rows[i - 1];
            mirror.index = before.index, mirror.glass = before.glass, mirror.abbe = before.abbe;
            mirror.glassCatalog = before.glassCatalog;
        }
    }
    // SI's thickness is the image's defocus from the last surface's gap.
    t.rows.back().gap += r.image.thickness * u;
    if (r.image.frame) {
        FrameChange f = *r.image.frame;
        for (double& d : f.decentre) d *= u;
        t.imageFrame = f;
    }
    const double object = r.object.thickness * u;
    if (r.haveObject && std::fabs(r.object.thickness) < kInfiniteObject) t.objectDistance = object;
    if (r.epd) t.entrancePupilDiameter = *r.epd * u;
    if (r.fno) t.designFNumber = *r.fno;
    if (r.imageNa && !r.fno) t.designFNumber = 1 / (2 * *r.imageNa);
    if (r.nao) t.objectNumericalAperture = *r.nao;
    setWavelengths(r);
    setFields(r);
    std::size_t kept = 0, bytes = 0;
    while (kept < t.comments.size() && (bytes += t.comments[kept].size()) <= kMaxCommentBytes) ++kept;
    t.comments.resize(kept);
    return t;
}

// The first command's name, upper case, without reading further.
std::string firstCommand(const std::string& text) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        const auto bang = line.find('!');
        std::istringstream words(line.substr(0, bang));
        std::string first;
        if (!(words >> first)) continue;
        return upperCase(first.substr(0, first.find(';')));
    }
    return "";
}

}  // namespace

LensTable parseCodeV(const std::string& bytes, const std::string& name) {
    SeqReader r;
    r.name = name;
    const std::string text = toUtf8Text(bytes, name);
    const std::vector<Command> commands = splitCommands(text, name);
    int lastLine = 0;
    for (const Command& c : commands) {
        lastLine = c.line;
        if (c.name[0] == '\'') {
            readPrivateGlass(r, c);
            continue;
        }
        const auto h = handlers().find(handlerName(c.name));
        if (h == handlers().end())
            r.fail(c.line, "command " + c.name.substr(0, 40) + " is not read by lenslab (docs/prescriptions.md lists the Code V commands it reads)");
        // The handlers tell commands apart by the name they are filed under (YAN from XAN, DAR from
        // BEN): a spelled-out command (CIRCLE, YANGLE) goes to its handler as that name.
        Command named = c;
        named.name = h->first;
        h->second(r, named);
    }
    if (commands.empty()) r.fail(1, "empty file: no Code V commands");
    LensTable t = assemble(r, lastLine);
    // A file cut short loses its last surfaces and still reads as a lens: without the image surface
    // and the closing GO nothing shows the end was reached.
    if (!r.haveImage && !r.closed)
        t.warnings.push_back({lastLine, name + " ends at line " + std::to_string(lastLine) +
                                            " with neither an image surface (SI) nor GO: the file may be cut short; read as the " +
                                            std::to_string(t.rows.size()) + " surfaces it gives"});
    return t;
}

bool looksLikeCodeV(const std::string& text) {
    const std::string first = firstCommand(text);
    for (const char* k : {"RDM", "LEN", "TIT", "TITLE", "DIM", "SO", "WL", "EPD", "FNO", "NAO", "YAN", "XAN", "PRV"})
        if (first == k) return true;
    return false;
}

}  // namespace lenslab
