using CommunityToolkit.Mvvm.Input;
using OperatorPanel.StlGen;

namespace OperatorPanel.ViewModels.Generate;

/// <summary>Save: the package's files into a folder the operator picks, each written atomically (HandlerPackage.TryWrite).</summary>
public sealed partial class GenerateCodeViewModel
{
    /// <summary>"Filler" -> "Filler-handler.awl", "Filler-symbols.txt", "Filler-README.txt" (and "Filler-merged.awl").</summary>
    public string FileStem => HandlerPackage.FileStem(Station);

    /// <summary>SaveCommand: asks for a folder and writes the files; enabled after a Generate without errors.</summary>
    [RelayCommand(CanExecute = nameof(CanSave))]
    private void Save()
    {
        if (_package is not { Ok: true } package || _files.PickFolder("Save the PLC code in") is not { } folder)
        {
            return;
        }

        if (!package.TryWrite(folder, out _, out var error))
        {
            Message = $"Not saved: {error}";
            return;
        }

        Message = $"Saved {string.Join(", ", package.Files.Select(f => f.Name))} in {folder}.";
    }
}
