// robowire/core/detail/check.hpp - internal: a table is checked once, when
// it is built at compile time. A broken table fails to compile; the
// compiler's message names the rule (one of the functions below), the
// message type and, in the call it shows, the message and field names.
#pragma once

#include "../config.hpp"  // first: the C++ version check

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <utility>

#include "../bits.hpp"
#include "../wire.hpp"

namespace robowire::detail {

// Not constexpr: reaching one of them while a table is checked at compile
// time is the compile error. Each names what is wrong.
inline void table_fields_out_of_offset_order(std::string_view /*message*/, std::string_view /*field*/) noexcept {}
inline void table_fields_overlap(std::string_view /*message*/, std::string_view /*field*/) noexcept {}
inline void table_field_beyond_message_size(std::string_view /*message*/, std::string_view /*field*/) noexcept {}
inline void table_fixed_byte_beyond_message_size(std::string_view /*message*/, std::size_t /*offset*/) noexcept {}
inline void table_message_longer_than_65535_bytes(std::string_view /*message*/) noexcept {}
inline void table_fixed_byte_under_field(std::string_view /*message*/, std::string_view /*field*/) noexcept {}
inline void table_leaves_struct_members_without_field(std::string_view /*message*/, std::size_t /*members*/,
                                                      std::size_t /*fields_plus_members_not_on_wire*/) noexcept {}

// Converts to any member type: counts an aggregate's members by how many it
// initialises.
struct any_member {
    template <class T>
    operator T&() const&& noexcept;  // declared only: used in unevaluated operands
};
template <class M, std::size_t... I>
constexpr bool initialisable_with(std::index_sequence<I...>) noexcept {
    return requires { M{((void)I, any_member{})...}; };
}
// Members of aggregate M (0 when M is not an aggregate). Used only to word
// the error below: it tries every count up to the answer.
template <class M, std::size_t N = 0>
constexpr std::size_t aggregate_member_count() noexcept {
    if constexpr (!std::is_aggregate_v<M>) return 0;
    else if constexpr (N >= 64 || !initialisable_with<M>(std::make_index_sequence<N + 1>{})) return N;
    else return aggregate_member_count<M, N + 1>();
}
// Aggregate M has exactly N members (true when M is not an aggregate): two tries.
template <class M, std::size_t N>
constexpr bool aggregate_has_members() noexcept {
    if constexpr (!std::is_aggregate_v<M>) return true;
    else
        return initialisable_with<M>(std::make_index_sequence<N>{}) &&
               !initialisable_with<M>(std::make_index_sequence<N + 1>{});
}

// The bits a one-byte bit field of type F takes in its byte; 0 for other fields.
template <class F>
inline constexpr unsigned bits_mask_v = [] {
    if constexpr (F::kind == wire_kind::bits && F::count == 1)
        return static_cast<unsigned>(low_mask(F::wire_type::width) << F::wire_type::lo);
    else return 0u;
}();

// Checks a message or record table; returns it unchanged. MembersMatch:
// every struct member is on the wire (a field) or declared as not on it
// (members_not_on_wire), worked out by the caller from the same table.
template <class Table, bool MembersMatch>
constexpr const Table& checked_table(const Table& t, std::bool_constant<MembersMatch>) noexcept {
    std::size_t prev_offset = 0, end = 0;
    std::size_t bits_byte = static_cast<std::size_t>(-1);
    unsigned bits_used = 0;
    // Declared sizes bound every field and fixed byte.
    const std::size_t limit = t.declared_size ? t.declared_size : t.declared_max_input;
    // one lambda over the fields as a pack (none per field type), then a loop
    t.fields.apply([&](const auto&... fs) {
        constexpr std::size_t n = sizeof...(fs);
        const std::string_view name[] = {fs.name..., {}};
        const std::size_t offset[] = {fs.offset..., 0};
        const std::size_t end_of[] = {fs.end()..., 0};
        const unsigned masks[] = {bits_mask_v<std::remove_cvref_t<decltype(fs)>>..., 0};
        for (std::size_t i = 0; i < n; ++i) {
            if (offset[i] < prev_offset) table_fields_out_of_offset_order(t.name, name[i]);
            const unsigned mask = masks[i];
            if (mask != 0 && offset[i] == bits_byte) {  // bit fields sharing a byte: their bits must not overlap
                if ((bits_used & mask) != 0) table_fields_overlap(t.name, name[i]);
                bits_used |= mask;
            } else {
                if (offset[i] < end) table_fields_overlap(t.name, name[i]);
                bits_byte = mask != 0 ? offset[i] : static_cast<std::size_t>(-1);
                bits_used = mask;
            }
            if (limit != 0 && end_of[i] > limit) table_field_beyond_message_size(t.name, name[i]);
            for (const auto& b : t.fixed)
                if (b.offset >= offset[i] && b.offset < end_of[i]) table_fixed_byte_under_field(t.name, name[i]);
            prev_offset = offset[i];
            if (end_of[i] > end) end = end_of[i];
        }
    });
    for (const auto& b : t.fixed) {
        if (limit != 0 && b.offset >= limit) table_fixed_byte_beyond_message_size(t.name, b.offset);
        if (b.offset > 0xFFFF) table_message_longer_than_65535_bytes(t.name);  // error offsets are 16 bits
    }
    if (end > 0xFFFF || limit > 0xFFFF) table_message_longer_than_65535_bytes(t.name);
    if constexpr (!MembersMatch)
        table_leaves_struct_members_without_field(t.name, aggregate_member_count<typename Table::message_type>(),
                                                  Table::field_count + t.members_not_on_wire);
    return t;
}

}  // namespace robowire::detail
