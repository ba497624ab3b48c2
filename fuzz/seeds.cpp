// Seeds made from each protocol's variant (its one list of messages): every
// message, default-constructed, encoded for the decoding harnesses, and every
// alternative's index byte for the round-trip harnesses. A new message gets
// its seeds without a list edited here.
//   fuzz_seeds --write fuzz/corpus   adds the seeds the corpus lacks (files named by content)
//   fuzz_seeds --check fuzz/corpus   fails when the corpus lacks one (a ctest)
// Golden vectors and edge cases from the documents are in fuzz/seeds.py.
#include <robowire/robowire.hpp>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace {

using seed = std::vector<std::uint8_t>;
namespace bw = robowire::buwizz3;
namespace nb = robowire::navbot;
namespace osp = robowire::osp;

template <class B>
seed to_seed(const B& b) {
    return seed(b.begin(), b.end());
}

// The wire form of every alternative of Variant, default-constructed.
template <class Variant, class Encode>
std::vector<seed> each_encoded(Encode encode) {
    std::vector<seed> out;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        (out.push_back(to_seed(encode(Variant{std::in_place_index<I>}).value())), ...);
    }(std::make_index_sequence<std::variant_size_v<Variant>>{});
    return out;
}

// One byte per alternative: the round-trip harnesses pick the alternative
// from their first byte (`base + index`).
template <class Variant>
std::vector<seed> each_index(std::uint8_t base = 0) {
    std::vector<seed> out;
    for (std::size_t i = 0; i < std::variant_size_v<Variant>; ++i) out.push_back({static_cast<std::uint8_t>(base + i)});
    return out;
}

std::vector<seed> joined(std::uint8_t first, const std::vector<seed>& parts) {
    seed s{first};
    for (const auto& p : parts) s.insert(s.end(), p.begin(), p.end());
    return {s};
}

std::vector<seed> operator+(std::vector<seed> a, const std::vector<seed>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

// The seeds with a first byte in front (the differential harnesses' mode).
std::vector<seed> prefixed(std::uint8_t mode, std::vector<seed> v) {
    for (auto& s : v) s.insert(s.begin(), mode);
    return v;
}

// harness name (fuzz/harnesses.txt) -> its seeds
std::vector<std::pair<std::string, std::vector<seed>>> all_seeds() {
    const auto any = [](const auto& v) { return robowire::encode(v); };
    const auto osp_frames = each_encoded<osp::message>([](const osp::message& m) { return osp::encode(m); });
    return {
        {"buwizz3_command", each_encoded<bw::command>(any)},
        {"buwizz3_notification", each_encoded<bw::notification>(any)},
        {"navbot_frame", each_encoded<nb::message>(any)},
        {"osp_decode", osp_frames},
        {"osp_scanner", joined(3, osp_frames)},  // first byte: the chunk sizes
        {"roundtrip_buwizz3", each_index<bw::command>() + each_index<bw::notification>(0x80)},
        {"roundtrip_navbot", each_index<nb::message>()},
        {"roundtrip_osp", each_index<osp::message>()},
        {"diff_buwizz3", prefixed(0, each_encoded<bw::command>(any)) + prefixed(1, each_encoded<bw::notification>(any)) +
                             prefixed(2, {{0}, {1}, {2}}) + prefixed(3, each_index<bw::command>())},
        {"diff_navbot", prefixed(0, each_encoded<nb::message>(any)) + prefixed(1, {{}})},
        {"diff_osp", prefixed(0, osp_frames) + prefixed(1, each_index<osp::message>())},
    };
}

// FNV-1a, 64 bits: a stable file name for a seed's content.
std::string name_of(const seed& s) {
    std::uint64_t h = 0xcbf29ce484222325u;
    for (auto b : s) h = (h ^ b) * 0x100000001b3u;
    char buf[32];
    std::snprintf(buf, sizeof buf, "msg-%016llx", static_cast<unsigned long long>(h));
    return buf;
}

seed read_file(const std::filesystem::path& p) {
    std::ifstream f(p, std::ios::binary);
    return seed((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3 || (std::strcmp(argv[1], "--write") != 0 && std::strcmp(argv[1], "--check") != 0)) {
        std::fprintf(stderr, "usage: %s --write|--check CORPUS_DIR\n", argv[0]);
        return 2;
    }
    const bool write = std::strcmp(argv[1], "--write") == 0;
    const std::filesystem::path corpus(argv[2]);
    int missing = 0, written = 0, total = 0;
    for (const auto& [harness, seeds] : all_seeds()) {
        const auto dir = corpus / harness;
        if (!std::filesystem::is_directory(dir)) {
            std::fprintf(stderr, "no corpus folder %s (is %s in fuzz/harnesses.txt?)\n", dir.c_str(), harness.c_str());
            return 2;
        }
        std::set<seed> have;  // already in the corpus under any name
        for (const auto& e : std::filesystem::directory_iterator(dir))
            if (e.is_regular_file()) have.insert(read_file(e.path()));
        for (const auto& s : seeds) {
            ++total;
            if (!have.insert(s).second) continue;
            const auto p = dir / name_of(s);
            if (write) {
                std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(s.data()),
                                                         static_cast<std::streamsize>(s.size()));
                ++written;
            } else {
                std::printf("missing seed %s (run: fuzz_seeds --write fuzz/corpus)\n", p.c_str());
                ++missing;
            }
        }
    }
    std::printf("%d seeds from the variants, %d written, %d missing\n", total, written, missing);
    return missing ? 1 : 0;
}
