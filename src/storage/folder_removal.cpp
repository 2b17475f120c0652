#include "storage/folder_removal.hpp"

#include <unistd.h>

namespace sd::storage {

FolderRemoval::FolderRemoval(std::filesystem::path folder) : folder_(std::move(folder)) {
  if (!std::filesystem::exists(std::filesystem::symlink_status(folder_))) {
    done_ = true;
    return;
  }
  aside_ = folder_.parent_path() / (".deleting-" + folder_.filename().string() + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(aside_);  // left by an earlier crash of this same pid
  std::filesystem::rename(folder_, aside_);
}

FolderRemoval::~FolderRemoval() {
  if (done_) return;
  std::error_code ignored;
  std::filesystem::rename(aside_, folder_, ignored);
}

void FolderRemoval::commit() {
  if (done_) return;
  done_ = true;
  std::error_code ignored;
  std::filesystem::remove_all(aside_, ignored);
}

}  // namespace sd::storage
