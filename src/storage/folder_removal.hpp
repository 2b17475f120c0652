#pragma once
// Removing a folder together with the rows that name it, so that neither outlives the other.
// The folder is first renamed to a hidden sibling (".deleting-..."; names users give never
// start with a dot, so no project or design can be created there): inside the caller's
// transaction that is one atomic step that can be undone. Only once the rows are gone is the
// hidden folder deleted; a crash then leaves a hidden folder, never one a new project or
// design of the same name or id would reuse.
#include <filesystem>
#include <string>

namespace sd::storage {

class FolderRemoval {
 public:
  /// Sets `folder` aside (nothing to do when it does not exist). Throws std::filesystem_error.
  explicit FolderRemoval(std::filesystem::path folder);
  /// Without commit(), the folder goes back where it was.
  ~FolderRemoval();
  FolderRemoval(const FolderRemoval&) = delete;
  FolderRemoval& operator=(const FolderRemoval&) = delete;

  /// The rows are gone: delete the folder for good. Links in it are removed, never followed.
  /// A folder that cannot be deleted stays hidden; that is not an error of the removal.
  void commit();

 private:
  std::filesystem::path folder_, aside_;
  bool done_ = false;
};

}  // namespace sd::storage
