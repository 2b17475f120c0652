#include "storage/power_cut.hpp"

#include <signal.h>
#include <sqlite3.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>

namespace sd::storage {

namespace {

struct Plan {
  std::int64_t checkpoint = 0;  // N: 0 = off
  std::int64_t write = 0;       // K
};

const Plan& plan() {
  static const Plan p = [] {
    Plan out;
    const char* text = std::getenv("SWARMDESIGN_POWER_CUT");
    if (!text) return out;
    const std::string s(text);
    const auto colon = s.find(':');
    // Not a number: 0, and the plan is dropped below.
    out.checkpoint = std::strtoll(s.substr(0, colon).c_str(), nullptr, 10);
    out.write = colon == std::string::npos ? 1 : std::strtoll(s.substr(colon + 1).c_str(), nullptr, 10);
    if (out.checkpoint < 1 || out.write < 1) out = {};
    return out;
  }();
  return p;
}

std::atomic<std::int64_t> checkpoints_begun = 0;  // design-database writes of this process
thread_local std::int64_t writes_left = 0;       // > 0: this thread's writes count down to the cut

[[noreturn]] void cut() {
  ::kill(::getpid(), SIGKILL);
  std::abort();  // not reached
}

// A file of the shim: SQLite allocates szOsFile bytes; the real VFS's file follows ours.
struct ShimFile {
  sqlite3_file base;
  sqlite3_file* real;
};

sqlite3_vfs* real_vfs = nullptr;
sqlite3_vfs shim_vfs;

sqlite3_file* real(sqlite3_file* f) { return reinterpret_cast<ShimFile*>(f)->real; }

int shim_write(sqlite3_file* f, const void* data, int amount, sqlite3_int64 offset) {
  if (writes_left > 0 && --writes_left == 0) {
    real(f)->pMethods->xWrite(real(f), data, amount / 2, offset);  // torn: half of it reaches the file
    cut();
  }
  return real(f)->pMethods->xWrite(real(f), data, amount, offset);
}

int shim_close(sqlite3_file* f) { return real(f)->pMethods->xClose(real(f)); }
int shim_read(sqlite3_file* f, void* data, int amount, sqlite3_int64 offset) {
  return real(f)->pMethods->xRead(real(f), data, amount, offset);
}
int shim_truncate(sqlite3_file* f, sqlite3_int64 size) { return real(f)->pMethods->xTruncate(real(f), size); }
int shim_sync(sqlite3_file* f, int flags) { return real(f)->pMethods->xSync(real(f), flags); }
int shim_file_size(sqlite3_file* f, sqlite3_int64* size) { return real(f)->pMethods->xFileSize(real(f), size); }
int shim_lock(sqlite3_file* f, int level) { return real(f)->pMethods->xLock(real(f), level); }
int shim_unlock(sqlite3_file* f, int level) { return real(f)->pMethods->xUnlock(real(f), level); }
int shim_check_reserved(sqlite3_file* f, int* out) { return real(f)->pMethods->xCheckReservedLock(real(f), out); }
int shim_file_control(sqlite3_file* f, int op, void* arg) { return real(f)->pMethods->xFileControl(real(f), op, arg); }
int shim_sector_size(sqlite3_file* f) { return real(f)->pMethods->xSectorSize(real(f)); }
int shim_device(sqlite3_file* f) { return real(f)->pMethods->xDeviceCharacteristics(real(f)); }
int shim_shm_map(sqlite3_file* f, int region, int size, int extend, void volatile** out) {
  return real(f)->pMethods->xShmMap(real(f), region, size, extend, out);
}
int shim_shm_lock(sqlite3_file* f, int offset, int n, int flags) {
  return real(f)->pMethods->xShmLock(real(f), offset, n, flags);
}
void shim_shm_barrier(sqlite3_file* f) { real(f)->pMethods->xShmBarrier(real(f)); }
int shim_shm_unmap(sqlite3_file* f, int remove) { return real(f)->pMethods->xShmUnmap(real(f), remove); }
int shim_fetch(sqlite3_file* f, sqlite3_int64 offset, int amount, void** out) {
  return real(f)->pMethods->xFetch(real(f), offset, amount, out);
}
int shim_unfetch(sqlite3_file* f, sqlite3_int64 offset, void* page) {
  return real(f)->pMethods->xUnfetch(real(f), offset, page);
}

const sqlite3_io_methods shim_methods = {
    3,           shim_close,     shim_read,      shim_write,         shim_truncate,     shim_sync,
    shim_file_size, shim_lock,   shim_unlock,    shim_check_reserved, shim_file_control, shim_sector_size,
    shim_device, shim_shm_map,   shim_shm_lock,  shim_shm_barrier,   shim_shm_unmap,    shim_fetch,
    shim_unfetch,
};

int shim_open(sqlite3_vfs*, sqlite3_filename name, sqlite3_file* f, int flags, int* out_flags) {
  auto* shim = reinterpret_cast<ShimFile*>(f);
  shim->real = reinterpret_cast<sqlite3_file*>(shim + 1);
  shim->real->pMethods = nullptr;
  const int rc = real_vfs->xOpen(real_vfs, name, shim->real, flags, out_flags);
  // SQLite closes a file whose pMethods is set, even when the open failed.
  shim->base.pMethods = shim->real->pMethods ? &shim_methods : nullptr;
  return rc;
}

}  // namespace

void install_power_cut_if_asked() {
  if (plan().checkpoint == 0) return;
  static std::once_flag once;
  std::call_once(once, [] {
    real_vfs = sqlite3_vfs_find(nullptr);
    if (!real_vfs || real_vfs->iVersion < 1) return;
    shim_vfs = *real_vfs;  // every other call goes to the real VFS as it is
    shim_vfs.szOsFile = static_cast<int>(sizeof(ShimFile)) + real_vfs->szOsFile;
    shim_vfs.zName = "swarmdesign-power-cut";
    shim_vfs.xOpen = shim_open;
    sqlite3_vfs_register(&shim_vfs, 1);
  });
}

PowerCutWindow::PowerCutWindow() {
  if (plan().checkpoint == 0) return;
  armed_ = ++checkpoints_begun == plan().checkpoint;
  if (armed_) writes_left = plan().write;
}

PowerCutWindow::~PowerCutWindow() {
  if (armed_) writes_left = 0;
}

void PowerCutWindow::committed() {
  if (armed_) cut();
}

}  // namespace sd::storage
