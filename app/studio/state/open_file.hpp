#pragma once
/// \file open_file.hpp
/// Opening a user's file in the studio, from the file dialog, a drop on the window or the recent
/// list: what kind of file it is (a cloud, labels, a ground truth, a configuration, a session, a
/// pairs file or manifest, a matcher's correspondences, `pagor bench --out` results, a floor plan,
/// a KITTI root) and where in the state it goes.

#include <string>
#include <vector>

#include "state/app_state.hpp"

namespace pagor::studio {

/// What a file is, told by its extension and, for .json and .txt, its first lines. Throws
/// InputError naming the file when it cannot be read or is of no kind the studio opens.
FilePurpose classify_file(const std::string& path);

/// Whether `data` names enough to run: files mode needs both clouds or a matcher's correspondences
/// (which run alone, or verified on both clouds).
bool data_ready(const PairSource& data);

/// What opening a file changed, so that the studio re-runs what it must.
struct Opened {
  bool data = false;     ///< the data changed: open it
  bool config = false;   ///< the configuration changed: re-run
  bool session = false;  ///< `state.session_path` names a session to load
  bool bench = false;    ///< `state.bench` names a set or results to open
  std::string what;      ///< one line for the user ("source cloud: x.pcd")
};

/// Puts `path` where `purpose` says (`any`: where its kind belongs; a cloud becomes the source
/// when files mode has none, else the target; labels follow the cloud of the same stem). Throws
/// pagor::Error naming the file when it cannot be used.
Opened open_file_into(AppState& state, const std::string& path, FilePurpose purpose);

/// Several files at once (a drop): each as open_file_into, two clouds as source and target in
/// the order given. Errors are collected, not thrown: one line each in `errors`.
Opened open_files_into(AppState& state, const std::vector<std::string>& paths,
                       std::vector<std::string>& errors);

/// The extensions a purpose lists in the file dialog (empty: every file).
std::vector<std::string> purpose_extensions(FilePurpose purpose);
/// A few words for the dialog's title ("source cloud", "configuration", ...).
const char* purpose_name(FilePurpose purpose);

/// Whether the first pair line of `path` is two frame numbers: a KITTI pairs file, not a manifest.
bool is_kitti_pairs_file(const std::string& path);

/// The first line of `path` that is neither blank nor a comment (`#` to the end of a line), split
/// into words. Throws InputError naming the file as `what` ("the pairs file") when it cannot be
/// read or has no such line.
std::vector<std::string> first_words(const std::string& path, const std::string& what = "the file");

}  // namespace pagor::studio
