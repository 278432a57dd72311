// SPDX-License-Identifier: MIT
#pragma once
// The desktop's own file dialog, as a child process (zenity, or kdialog on KDE), so the window
// keeps drawing while it is open and no toolkit is linked in. Debian 12 packages none of the
// small dialog libraries; both programs are what GNOME and KDE desktops use themselves.

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sandglass {

class ChildProcess;

/// What the dialog is for: picks the title, open or save, files or a folder, and the filter.
enum class FileChoice {
    OpenState,        ///< a .sand file to open
    SaveState,        ///< where to save a .sand file
    Export,           ///< where to export the sand (.ply, .vox, .obj, .stl, .glb)
    Model,            ///< a model file for the hourglass or sculpture
    Draft,            ///< a PNG or JPEG for the canvas's draft
    DiggerBody,       ///< a model file for the digger's body
    ScreenshotFolder, ///< the folder screenshots go to
};

/// What a closed dialog gave.
struct ChosenFile {
    FileChoice choice;  ///< what it was opened for
    std::string path;   ///< the path chosen; empty when the user cancelled
};

/// The program and arguments that show the dialog for `choice`, starting at `startPath`;
/// `program` is "zenity", "kdialog" or another program taking zenity's arguments.
std::vector<std::string> fileChooserCommand(const std::string& program, FileChoice choice, const std::string& startPath);

/// One dialog at a time, polled once per frame.
class FileChooser {
public:
    FileChooser();
    ~FileChooser(); ///< closes a dialog still open
    FileChooser(const FileChooser&) = delete;
    FileChooser& operator=(const FileChooser&) = delete;

    /// Opens the dialog; returns an empty string, or the one-line reason it cannot (another is
    /// open, no dialog program found). The program is $SANDGLASS_FILE_CHOOSER when set (it takes
    /// zenity's arguments), else zenity, else kdialog, looked up in PATH.
    std::string open(FileChoice choice, const std::string& startPath);
    /// Once the dialog has closed: what it gave (once). Nothing while it is open or none is.
    std::optional<ChosenFile> poll();
    bool isOpen() const { return child_ != nullptr; } ///< a dialog is showing

private:
    std::unique_ptr<ChildProcess> child_; // the dialog while it is open
    FileChoice choice_ = FileChoice::OpenState;
    std::string received_; // what the child has written so far
};

} // namespace sandglass
