// tests/vectors/vectors.json through the library: every message vector decodes
// to its message, its integer, boolean, float and enumeration fields equal the
// file's, and it encodes back to the same bytes; every error vector gives its
// code, offset and describe_error line; the OSP streams give their frames; the
// NAVBOT multi-frame messages fragment to their frames and reassemble.
// Usage: robowire_vectors PATH/vectors.json. Prints "N passed, M failed".
#include <robowire/buwizz3.hpp>
#include <robowire/navbot.hpp>
#include <robowire/osp.hpp>
#include <robowire/reflect.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

namespace {

using json = nlohmann::json;
int passed = 0, failed = 0;

void check(bool ok, const std::string& what) {
    if (ok) {
        ++passed;
    } else {
        ++failed;
        std::cout << "FAIL: " << what << '\n';
    }
}

std::vector<std::uint8_t> bytes_of(const std::string& hex) {
    std::vector<std::uint8_t> out;
    std::string digits;
    for (const char c : hex)
        if (c != ' ') digits += c;
    for (std::size_t i = 0; i + 1 < digits.size(); i += 2)
        out.push_back(static_cast<std::uint8_t>(std::stoul(digits.substr(i, 2), nullptr, 16)));
    return out;
}

// One element against the file's value (a number, a boolean, an enumerator's name).
template <class E>
bool element_equals(const E& e, const json& want) {
    if constexpr (std::is_same_v<E, bool>) {
        return want.is_boolean() && want.get<bool>() == e;
    } else if constexpr (std::is_enum_v<E>) {
        return want.is_string() ? robowire::enum_name(e) == want.get<std::string>()
                                : want.is_number_integer() && want.get<long long>() == static_cast<long long>(e);
    } else if constexpr (std::is_floating_point_v<E>) {
        return want.is_number() &&
               std::fabs(static_cast<double>(e) - want.get<double>()) <= 1e-9 * std::fabs(want.get<double>());
    } else {
        return want.is_number_integer() && want.get<long long>() == static_cast<long long>(e);
    }
}

// The fields of decoded message m that are numbers, booleans or enumerators, against the file's.
template <class M>
void check_fields(const M& m, const json& fields, const std::string& what) {
    robowire::for_each_value(m, [&](const auto& f, auto elements) {
        using F = std::remove_cvref_t<decltype(f)>;
        constexpr auto kind = robowire::value_kind_v<F>;
        if constexpr (kind == robowire::value_kind::integer || kind == robowire::value_kind::boolean ||
                      kind == robowire::value_kind::floating || kind == robowire::value_kind::enumeration) {
            const std::string name(f.name);
            if (!fields.contains(name)) return;
            const json& want = fields[name];
            bool ok;
            if (want.is_null()) {
                ok = elements.empty();  // an absent optional block
            } else if (F::is_array) {
                ok = want.is_array() && want.size() == elements.size();
                for (std::size_t i = 0; ok && i < elements.size(); ++i) ok = element_equals(elements[i], want[i]);
            } else {
                ok = elements.size() == 1 && element_equals(elements[0], want);
            }
            check(ok, what + "." + name + ": expected " + want.dump());
        }
    });
}

// The name of the alternative a variant holds.
template <class Variant>
std::string_view name_of(const Variant& v) {
    return std::visit([](const auto& m) { return robowire::table_v<std::remove_cvref_t<decltype(m)>>.name; }, v);
}

struct outcome {
    bool ok = false;
    std::string message;  // the decoded message's name
    robowire::error error{};
    std::string line;                   // describe_error's line
    std::vector<std::uint8_t> encoded;  // the decoded message encoded again
};

template <class Variant, class Result, class Encode, class Describe>
outcome finish(const Result& r, const json& fields, const std::string& what, Encode encode, Describe describe) {
    outcome o;
    o.ok = static_cast<bool>(r);
    if (!o.ok) {
        o.error = r.error();
        o.line = std::string(describe(r.error()));
        return o;
    }
    const Variant& v = *r;
    o.message = std::string(name_of(v));
    std::visit([&](const auto& m) { check_fields(m, fields, what); }, v);
    const auto back = encode(v);
    if (back) o.encoded.assign(back->begin(), back->end());
    return o;
}

// BuWizz3 without a direction: 0x01 is the only key that is a notification alone (the document's
// status); every error vector without a direction is a command or the status.
outcome decode(const std::string& protocol, const std::string& direction, const std::vector<std::uint8_t>& in,
               const json& fields, const std::string& what) {
    namespace bw = robowire::buwizz3;
    namespace nb = robowire::navbot;
    namespace osp = robowire::osp;
    const std::span<const std::uint8_t> s(in.data(), in.size());
    char buf[256];
    if (protocol == "buwizz3") {
        const bool notification = direction == "notification" || (direction.empty() && !in.empty() && in[0] == 0x01);
        const auto encode = [](const auto& v) { return robowire::encode(v); };
        if (notification)
            return finish<bw::notification>(
                bw::decode_notification(s), fields, what, encode,
                [&](const robowire::error& e) { return robowire::describe_error<bw::notification>(e, s, buf); });
        return finish<bw::command>(bw::decode_command(s), fields, what, encode, [&](const robowire::error& e) {
            return robowire::describe_error<bw::command>(e, s, buf);
        });
    }
    if (protocol == "navbot")
        return finish<nb::message>(
            nb::decode_frame(s), fields, what, [](const auto& v) { return robowire::encode(v); },
            [&](const robowire::error& e) { return nb::describe_error(e, s, buf); });
    return finish<osp::message>(
        osp::decode(s), fields, what, [](const osp::message& v) { return osp::encode(v); },
        [&](const robowire::error& e) { return osp::describe_error(e, s, buf); });
}

std::string str_or_empty(const json& j) { return j.is_string() ? j.get<std::string>() : std::string(); }

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: robowire_vectors PATH/vectors.json\n";
        return 2;
    }
    std::ifstream file(argv[1]);
    if (!file) {
        std::cerr << "cannot open " << argv[1] << '\n';
        return 2;
    }
    const json data = json::parse(file);

    for (const auto& v : data.at("messages")) {
        const std::string what = v.at("protocol").get<std::string>() + " " + v.at("message").get<std::string>();
        const auto in = bytes_of(v.at("hex"));
        const outcome o = decode(v.at("protocol"), str_or_empty(v.at("direction")), in, v.at("fields"), what);
        check(o.ok && o.message == v.at("message").get<std::string>(),
              what + ": decodes to " + o.message + " / " + o.line);
        check(o.encoded == in, what + ": encodes back to " + v.at("hex").get<std::string>());
    }

    for (const auto& v : data.at("errors")) {
        const std::string what = v.at("protocol").get<std::string>() + " error " + v.at("hex").get<std::string>();
        const outcome o =
            decode(v.at("protocol"), str_or_empty(v.at("direction")), bytes_of(v.at("hex")), json::object(), what);
        check(!o.ok && robowire::name_of(o.error.code) == v.at("code").get<std::string>(),
              what + ": code " + std::string(robowire::name_of(o.error.code)));
        check(!o.ok && o.error.offset == v.at("offset").get<unsigned>(),
              what + ": offset " + std::to_string(o.error.offset));
        check(o.line == v.at("error").get<std::string>(), what + ": line '" + o.line + "'");
    }

    for (const auto& v : data.at("osp_scan")) {
        const auto stream = bytes_of(v.at("hex"));
        const std::string what = "osp scan " + v.at("hex").get<std::string>();
        // byte by byte and whole: the same frames
        for (const std::size_t chunk : {std::size_t{1}, stream.size()}) {
            robowire::osp::scanner sc;
            std::vector<std::vector<std::uint8_t>> frames;
            for (std::size_t i = 0; i < stream.size(); i += chunk) {
                const std::span<const std::uint8_t> part(stream.data() + i, std::min(chunk, stream.size() - i));
                sc.feed(part, [&](robowire::osp::scanner::frame_bytes f) { frames.emplace_back(f.begin(), f.end()); });
            }
            const auto& records = v.at("records");
            std::vector<outcome> got;
            for (std::size_t i = 0; i < frames.size(); ++i) {
                const json fields = i < records.size() ? records[i].value("fields", json::object()) : json::object();
                got.push_back(decode("osp", "", frames[i], fields, what));
            }
            bool ok = got.size() == records.size();
            for (std::size_t i = 0; ok && i < got.size(); ++i) {
                const auto& w = records[i];
                ok = w.contains("message")
                         ? got[i].ok && got[i].message == w.at("message").get<std::string>()
                         : !got[i].ok && got[i].line == w.at("error").get<std::string>() &&
                               robowire::name_of(got[i].error.code) == w.at("code").get<std::string>() &&
                               got[i].error.offset == w.at("offset").get<unsigned>();
            }
            check(ok, what + " in chunks of " + std::to_string(chunk) + ": " + std::to_string(got.size()) + " frames");
        }
    }

    namespace nb = robowire::navbot;
    for (const auto& v : data.at("navbot_multiframe")) {
        const std::string text = v.at("text");
        const std::string what = "navbot multi-frame " + text;
        const auto frames = nb::json_frames(text);
        const auto& want = v.at("frames");
        bool same = frames && frames->size() == want.size();
        for (std::size_t i = 0; same && i < want.size(); ++i) {
            const auto f = (*frames)[i];
            same = std::vector<std::uint8_t>(f.begin(), f.end()) == bytes_of(want[i]);
        }
        check(same, what + ": json_frames gives the frames");
        nb::reassembler<nb::max_payload> r;
        std::vector<std::string> outcomes;
        for (const auto& hex : want) {
            const auto in = bytes_of(hex);
            const auto st = r.push(std::span<const std::uint8_t>(in.data(), in.size()));
            outcomes.push_back(!st                                ? "error"
                               : *st == nb::reassembly::need_more ? "need_more"
                               : *st == nb::reassembly::complete  ? "complete"
                                                                  : "other");
        }
        check(outcomes == v.at("outcomes").get<std::vector<std::string>>(), what + ": outcomes");
        check(r.command() == v.at("command").get<unsigned>() && r.text() == text,
              what + ": text '" + std::string(r.text()) + "'");
    }
    for (const auto& v : data.at("navbot_reassembly")) {
        const std::string what = "navbot reassembly " + v.at("source").get<std::string>();
        nb::reassembler<nb::max_payload> r;
        const auto& frames = v.at("frames");
        const auto& outcomes = v.at("outcomes");
        check(frames.size() == outcomes.size(), what + ": an outcome per frame");
        for (std::size_t i = 0; i < frames.size() && i < outcomes.size(); ++i) {
            const auto in = bytes_of(frames[i]);
            const auto st = r.push(std::span<const std::uint8_t>(in.data(), in.size()));
            const std::string want = outcomes[i];
            if (want == "error") {
                check(!st && robowire::name_of(st.error().code) == v.at("error").at("code").get<std::string>() &&
                          st.error().offset == v.at("error").at("offset").get<unsigned>(),
                      what + ": frame " + std::to_string(i) + " is an error");
                continue;
            }
            const std::string got = !st                                ? "error"
                                    : *st == nb::reassembly::need_more ? "need_more"
                                    : *st == nb::reassembly::complete  ? "complete"
                                    : *st == nb::reassembly::duplicate ? "duplicate"
                                    : *st == nb::reassembly::restarted ? "restarted"
                                                                       : "other";
            check(got == want, what + ": frame " + std::to_string(i) + " " + got);
            if (want == "complete")
                check(r.text() == v.at("text").get<std::string>(), what + ": text " + std::string(r.text()));
        }
    }

    std::cout << passed << " passed, " << failed << " failed\n";
    return failed ? 1 : 0;
}
