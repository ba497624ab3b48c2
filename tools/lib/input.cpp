// Input read in blocks as it arrives (read(2): a pipe's data as soon as it is
// written), and line by line with CR, LF and CRLF line ends. Memory: one
// block and one line of at most input_stream::max_line bytes.
#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "tools.hpp"

namespace robowire::tools {

namespace {
constexpr std::size_t block = 1 << 16;
constexpr std::size_t peek_size = 4096;
}  // namespace

input_stream::~input_stream() {
    if (own_ && fd_ >= 0) ::close(fd_);
}

bool input_stream::open(const std::string& path, std::string& err) {
    name = path == "-" ? "stdin" : path;
    if (path == "-") {
        fd_ = 0;
    } else {
        fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
        if (fd_ < 0) {
            err = "cannot open " + path + ": " + std::strerror(errno);
            return false;
        }
        own_ = true;
    }
    struct stat st {};
    if (::fstat(fd_, &st) != 0) {
        err = "cannot read " + name + ": " + std::strerror(errno) + (path == "-" ? " (stdin is closed)" : "");
        return false;
    }
    if (S_ISDIR(st.st_mode)) {
        err = "cannot read " + name + ": it is a directory";
        return false;
    }
    return true;
}

void input_stream::open_text(std::string_view text, std::string n) {
    name = std::move(n);
    buf_.assign(text);
    // an argument ends where it ends: its last line is whole, not cut short
    if (buf_.empty() || (buf_.back() != '\n' && buf_.back() != '\r')) buf_ += '\n';
    pos_ = 0;
    eof_ = true;
}

void input_stream::open_source(std::function<std::size_t(char*, std::size_t)> source, std::string n) {
    name = std::move(n);
    source_ = std::move(source);
}

namespace {
// The first CR or LF in [p, e), or e: memchr over windows growing 4 times each
// (a file of CR line ends is not searched to its end for an LF at each line).
const char* line_end(const char* p, const char* e) {
    for (std::size_t window = 256;; window *= 4) {
        const char* lim = static_cast<std::size_t>(e - p) > window ? p + window : e;
        const auto* lf = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(lim - p)));
        const char* upto = lf ? lf : lim;
        if (const auto* cr = static_cast<const char*>(std::memchr(p, '\r', static_cast<std::size_t>(upto - p))))
            return cr;
        if (lf || lim == e) return upto;
        p = lim;
    }
}
}  // namespace

bool input_stream::fill() {
    if (eof_) return false;
    if (pos_ > 0 && pos_ == buf_.size()) {
        buf_.clear();
        pos_ = 0;
    } else if (pos_ > block) {
        buf_.erase(0, pos_);
        pos_ = 0;
    }
    if (flush_before_wait && fd_ >= 0) {
        pollfd pfd{fd_, POLLIN, 0};
        if (::poll(&pfd, 1, 0) == 0) flush_before_wait->flush();
    }
    const std::size_t old = buf_.size();
    buf_.resize(old + block);
    if (source_) {
        const std::size_t n = std::min(source_(buf_.data() + old, block), block);
        buf_.resize(old + n);
        if (n == 0) eof_ = true;
        return n > 0;
    }
    for (;;) {
        const ssize_t n = ::read(fd_, buf_.data() + old, block);
        if (n > 0) {
            buf_.resize(old + static_cast<std::size_t>(n));
            return true;
        }
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) error = "cannot read " + name + ": " + std::strerror(errno);
        buf_.resize(old);
        eof_ = true;
        return false;
    }
}

std::span<const std::uint8_t> input_stream::peek() {
    // up to 4 KB, or less once a line has ended (a pipe written line by line is not waited for)
    auto line_ended = [&] {
        return std::any_of(buf_.begin() + static_cast<std::ptrdiff_t>(pos_), buf_.end(),
                           [](char c) { return c == '\n' || c == '\r'; });
    };
    while (buf_.size() - pos_ < peek_size && !line_ended() && fill()) {
    }
    const std::size_t n = std::min(peek_size, buf_.size() - pos_);
    return {reinterpret_cast<const std::uint8_t*>(buf_.data() + pos_), n};
}

std::span<const std::uint8_t> input_stream::read() {
    if (pos_ == buf_.size() && !fill()) return {};
    const std::span<const std::uint8_t> s(reinterpret_cast<const std::uint8_t*>(buf_.data() + pos_),
                                          buf_.size() - pos_);
    pos_ = buf_.size();
    return s;
}

bool input_stream::next_line(std::string_view& line, std::size_t& length, bool& ended) {
    std::size_t scanned = 0;  // bytes after pos_ known to hold no line end
    bool cutting = false;     // a line longer than max_line: its first bytes are in cut_
    length = 0;
    for (;;) {
        if (skip_lf_) {
            if (pos_ == buf_.size() && !fill()) {
                skip_lf_ = false;
                return false;
            }
            if (buf_[pos_] == '\n') ++pos_;
            skip_lf_ = false;
        }
        const char* b = buf_.data() + pos_;
        const char* e = buf_.data() + buf_.size();
        const char* end = line_end(b + scanned, e);
        if (end != e) {
            const auto n = static_cast<std::size_t>(end - b);
            skip_lf_ = *end == '\r';
            pos_ += n + 1;
            ended = true;
            if (cutting) {
                length += n;
                line = cut_;
            } else {
                length = n;
                line = std::string_view(b, n);
            }
            return true;
        }
        scanned = static_cast<std::size_t>(e - b);
        if (scanned >= max_line || cutting) {
            // a long line: keep its first bytes, drop the rest as it is read
            if (!cutting) cut_.assign(b, std::min<std::size_t>(64, scanned));
            cutting = true;
            length += scanned;
            pos_ = buf_.size();
            scanned = 0;
        }
        if (!fill()) {
            const std::size_t rest = buf_.size() - pos_;
            if (rest == 0 && !cutting) return false;
            ended = false;
            if (cutting) {
                length += rest;
                line = cut_;
            } else {
                length = rest;
                line = std::string_view(buf_.data() + pos_, rest);
            }
            pos_ = buf_.size();
            return true;
        }
    }
}

namespace {
// Calls fn(line) for each line of `first` (the last one possibly cut).
template <class Fn>
void each_line(std::span<const std::uint8_t> first, Fn&& fn) {
    std::size_t start = 0;
    for (std::size_t i = 0; i <= first.size(); ++i) {
        if (i == first.size() || first[i] == '\n' || first[i] == '\r') {
            if (i > start) fn(first.subspan(start, i - start));
            start = i + 1;
        }
    }
}
bool has_control_byte(std::span<const std::uint8_t> line) {
    return std::any_of(line.begin(), line.end(), [](std::uint8_t c) { return c < 0x20 && c != '\t'; });
}
}  // namespace

bool looks_binary(std::span<const std::uint8_t> first) {
    std::size_t dirty = 0, clean = 0;
    each_line(first, [&](std::span<const std::uint8_t> l) { ++(has_control_byte(l) ? dirty : clean); });
    return dirty > clean;
}

bool looks_like_hex_lines(std::span<const std::uint8_t> first) {
    std::size_t hex = 0, other = 0;
    each_line(first, [&](std::span<const std::uint8_t> l) { ++(looks_like_hex_text(l) ? hex : other); });
    return hex > other;
}

std::string control_byte(std::string_view line) {
    // the smallest byte first (a loop the compiler vectorizes): most lines have none below 0x20
    unsigned char least = 0xFF;
    for (const char c : line) least = std::min(least, static_cast<unsigned char>(c));
    if (least >= 0x20) return {};
    for (std::size_t i = 0; i < line.size(); ++i) {
        const auto c = static_cast<unsigned char>(line[i]);
        if (c < 0x20 && c != '\t') {
            char b[64];
            std::snprintf(b, sizeof b, "control byte 0x%02X at character %zu", c, i);
            return b;
        }
    }
    return {};
}

}  // namespace robowire::tools
