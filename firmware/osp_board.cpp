// The board loop of docs/osp.md (the device-side section), compiled as the
// page gives it: firmware/footprint copies that block into
// osp_board_loop.cpp. Here the board's UART driver and measurements come
// from the harness's volatile buffer and sink.
#include "harness.hpp"

std::size_t uart_read(std::uint8_t* data, std::size_t max) {
    const std::size_t n = size_in(max < sizeof input ? max : sizeof input);
    for (std::size_t i = 0; i < n; ++i) data[i] = input[i];
    return n;
}
void uart_write(const std::uint8_t* data, std::size_t size) {
    for (std::size_t i = 0; i < size; ++i) sink = data[i];
}
std::int32_t read_millivolts() { return static_cast<std::int32_t>(sink); }
std::int16_t read_milliamps() { return static_cast<std::int16_t>(sink); }
std::uint16_t read_soc_basis_points() { return static_cast<std::uint16_t>(sink); }

#include "osp_board_loop.cpp"
