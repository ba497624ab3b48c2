// set_field on an array member (one assertion, no cascade of errors).
// expect: scalar or enum members only
#include <robowire/buwizz3/commands.hpp>
#include <robowire/core/fields.hpp>

int main() {
    robowire::buwizz3::set_motor_data m{};
#ifdef ROBOWIRE_FIXED
    return robowire::set_field<&robowire::buwizz3::set_motor_data::brake_flags>(m, 3) ? 1 : 0;
#else
    return robowire::set_field<&robowire::buwizz3::set_motor_data::power>(m, 300) ? 1 : 0;
#endif
}
