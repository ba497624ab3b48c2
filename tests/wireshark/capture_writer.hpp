// Minimal capture file writers for the dissector tests: pcap (any link type),
// Android btsnoop (HCI UART H4) and pcapng (one interface, direction flags).
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace capture {

using byte_vector = std::vector<std::uint8_t>;

inline void put_le(byte_vector& o, std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) o.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}
inline void put_be(byte_vector& o, std::uint64_t v, int n) {
    for (int i = n - 1; i >= 0; --i) o.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

inline bool write_file(const std::string& path, const byte_vector& data) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const bool ok = std::fwrite(data.data(), 1, data.size(), f) == data.size();
    return std::fclose(f) == 0 && ok;
}

// Direction of a record: host -> device (sent) or device -> host (received).
enum class dir : std::uint8_t { sent, received };

// pcap, microsecond timestamps. For link type 201 (BLUETOOTH_HCI_H4_WITH_PHDR)
// pass with_direction: each record starts with a 4-byte big-endian direction.
class pcap {
public:
    pcap(std::uint32_t linktype, bool with_direction) : direction_(with_direction) {
        put_le(out_, 0xa1b2c3d4, 4);
        put_le(out_, 2, 2);
        put_le(out_, 4, 2);
        put_le(out_, 0, 4);
        put_le(out_, 0, 4);
        put_le(out_, 65535, 4);
        put_le(out_, linktype, 4);
    }
    void add(dir d, const byte_vector& data) {
        const std::uint32_t n = static_cast<std::uint32_t>(data.size() + (direction_ ? 4 : 0));
        ++count_;
        put_le(out_, 1700000000 + count_, 4);
        put_le(out_, 0, 4);
        put_le(out_, n, 4);
        put_le(out_, n, 4);
        if (direction_) put_be(out_, d == dir::received ? 1 : 0, 4);
        out_.insert(out_.end(), data.begin(), data.end());
    }
    bool save(const std::string& path) const { return write_file(path, out_); }

private:
    bool direction_;
    std::uint32_t count_ = 0;
    byte_vector out_;
};

// Android btsnoop log, datalink 1002 (HCI UART H4: the data starts with the packet type byte).
class btsnoop {
public:
    btsnoop() {
        for (const char c : std::string_view("btsnoop", 8)) out_.push_back(static_cast<std::uint8_t>(c));
        put_be(out_, 1, 4);
        put_be(out_, 1002, 4);
    }
    void add(dir d, const byte_vector& h4) {
        const bool command_or_event = !h4.empty() && (h4[0] == 0x01 || h4[0] == 0x04);
        ++count_;
        put_be(out_, h4.size(), 4);
        put_be(out_, h4.size(), 4);
        put_be(out_, (d == dir::received ? 1u : 0u) | (command_or_event ? 2u : 0u), 4);
        put_be(out_, 0, 4);
        // microseconds since year 0; 0x00dcddb30f2f8000 is 1970-01-01
        put_be(out_, 0x00dcddb30f2f8000ULL + (1700000000ULL + count_) * 1000000ULL, 8);
        out_.insert(out_.end(), h4.begin(), h4.end());
    }
    bool save(const std::string& path) const { return write_file(path, out_); }

private:
    std::uint64_t count_ = 0;
    byte_vector out_;
};

// pcapng with one interface; every packet carries the epb_flags direction
// (inbound: device -> host, outbound: host -> device).
class pcapng {
public:
    explicit pcapng(std::uint16_t linktype) {
        byte_vector shb;
        put_le(shb, 0x1a2b3c4d, 4);
        put_le(shb, 1, 2);
        put_le(shb, 0, 2);
        put_le(shb, 0xffffffffffffffffULL, 8);
        block(0x0a0d0d0a, shb);
        byte_vector idb;
        put_le(idb, linktype, 2);
        put_le(idb, 0, 2);
        put_le(idb, 0, 4);
        block(1, idb);
    }
    void add(dir d, const byte_vector& data) {
        byte_vector epb;
        ++count_;
        const std::uint64_t ts = (1700000000ULL + count_) * 1000000ULL;
        put_le(epb, 0, 4);
        put_le(epb, ts >> 32, 4);
        put_le(epb, ts & 0xffffffffu, 4);
        put_le(epb, data.size(), 4);
        put_le(epb, data.size(), 4);
        epb.insert(epb.end(), data.begin(), data.end());
        while (epb.size() % 4) epb.push_back(0);
        put_le(epb, 2, 2);  // epb_flags
        put_le(epb, 4, 2);
        put_le(epb, d == dir::received ? 1 : 2, 4);
        put_le(epb, 0, 4);  // opt_endofopt
        block(6, epb);
    }
    bool save(const std::string& path) const { return write_file(path, out_); }

private:
    void block(std::uint32_t type, const byte_vector& body) {
        const std::uint32_t n = static_cast<std::uint32_t>(12 + body.size());
        put_le(out_, type, 4);
        put_le(out_, n, 4);
        out_.insert(out_.end(), body.begin(), body.end());
        put_le(out_, n, 4);
    }
    std::uint64_t count_ = 0;
    byte_vector out_;
};

}  // namespace capture
