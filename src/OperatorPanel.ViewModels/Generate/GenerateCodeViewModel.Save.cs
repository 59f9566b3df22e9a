using System.Globalization;
using System.Text;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Generate;

/// <summary>Save: the generated texts into a folder the operator picks, each file written atomically (Core AtomicFile).</summary>
public sealed partial class GenerateCodeViewModel
{
    /// <summary>"Filler" -> "Filler-handler.awl", "Filler-symbols.txt", "Filler-README.txt" (and "Filler-merged.awl").</summary>
    public string FileStem
    {
        get
        {
            var chars = Station.Name.Select(c => char.IsAsciiLetterOrDigit(c) || c is '-' or '_' ? c : '_').ToArray();
            return chars.Length == 0 ? "station" + Station.Address.Address.ToString(CultureInfo.InvariantCulture) : new string(chars);
        }
    }

    private void Save()
    {
        if (_result is not { Ok: true } result || _files.PickFolder("Save the PLC code in") is not { } folder)
        {
            return;
        }

        var stem = FileStem;
        var files = new List<(string Name, byte[] Bytes)>
        {
            // The handler is plain ASCII (Micro/WIN imports it as is); the merged program keeps the user's bytes (Latin-1).
            ($"{stem}-handler.awl", Encoding.ASCII.GetBytes(result.AwlText)),
            ($"{stem}-symbols.txt", Encoding.ASCII.GetBytes(result.SymbolTableText)),
            ($"{stem}-README.txt", Encoding.ASCII.GetBytes(result.TechnicianText)),
        };
        if (_merge is { Ok: true } merge)
        {
            files.Add(($"{stem}-merged.awl", Encoding.Latin1.GetBytes(merge.MergedText)));
        }

        foreach (var (name, bytes) in files)
        {
            var path = Path.Combine(folder, name);
            if (!AtomicFile.TryWrite(path, bytes, out var error))
            {
                Message = $"Not saved: {path}: {error}";
                return;
            }
        }

        Message = $"Saved {string.Join(", ", files.Select(f => f.Name))} in {folder}.";
    }
}
