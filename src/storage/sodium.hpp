#pragma once
// libsodium must be initialised once before use; every storage file that uses it calls this.
namespace sd::storage {
void ensure_sodium();
}
