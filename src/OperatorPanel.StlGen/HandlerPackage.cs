using System.Collections.Immutable;
using System.Diagnostics.CodeAnalysis;
using System.Globalization;
using System.Text;
using OperatorPanel.Core.Messages;
using OperatorPanel.Core.Projects;
using OperatorPanel.StlGen.Merge;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen;

/// <summary>
/// What Generate PLC code and <c>opanel generate</c> save for one station, decided once for both: the handler
/// (<see cref="HandlerGenerator"/>), merged into the user's exported program when one is given (<see cref="HandlerMerger"/>),
/// the file names (STEM-handler.awl, STEM-symbols.txt, STEM-README.txt, STEM-merged.awl), the size limit of the user's
/// program and the writing (each file atomically, one byte per character: the generated text is ASCII, the user's lines
/// in the merged file go back in the code page they came in).
/// </summary>
public sealed record HandlerPackage
{
    /// <summary>An exported Micro/WIN program larger than this is not a program block.</summary>
    public const long MaxProgramBytes = 8 * 1024 * 1024;

    private HandlerPackage(string stem, HandlerGenerationResult handler, MergeResult? merge) => (Stem, Handler, Merge) = (stem, handler, merge);

    public string Stem { get; }

    public HandlerGenerationResult Handler { get; }

    /// <summary>The merge with the user's program; null when none was given or the handler itself was refused.</summary>
    public MergeResult? Merge { get; }

    /// <summary>True when there is something to save: a handler, and a merge without collisions if one was asked for.</summary>
    public bool Ok => Handler.Ok && Merge is null or { Ok: true };

    /// <summary>The files to save, name and text; empty unless <see cref="Ok"/>.</summary>
    public ImmutableArray<(string Name, string Text)> Files => !Ok ? [] :
    [
        ($"{Stem}-handler.awl", Handler.AwlText),
        ($"{Stem}-symbols.txt", Handler.SymbolTableText),
        ($"{Stem}-README.txt", Handler.TechnicianText),
        .. Merge is { } merge ? [($"{Stem}-merged.awl", merge.MergedText)] : Array.Empty<(string, string)>(),
    ];

    /// <summary>A station name as part of a file name: letters, digits, '-' and '_' kept, anything else '_'.</summary>
    public static string FileStem(ProjectStation station)
    {
        ArgumentNullException.ThrowIfNull(station);
        var chars = station.Name.Select(c => char.IsAsciiLetterOrDigit(c) || c is '-' or '_' ? c : '_').ToArray();
        return chars.Length == 0 ? "station" + station.Address.Address.ToString(CultureInfo.InvariantCulture) : new string(chars);
    }

    /// <summary>Generates the handler for <paramref name="options"/> and, with <paramref name="userProgram"/>, merges it in.</summary>
    public static HandlerPackage Generate(HandlerOptions options, string stem, string? userProgram = null)
    {
        ArgumentNullException.ThrowIfNull(options);
        ArgumentException.ThrowIfNullOrWhiteSpace(stem);
        var handler = HandlerGenerator.Generate(options);
        var merge = handler.Ok && userProgram is not null ? HandlerMerger.Merge(userProgram, options) : null;
        return new HandlerPackage(stem, handler, merge);
    }

    /// <summary>
    /// Reads a program exported from Micro/WIN. It is in the Windows code page; Latin-1 keeps one character per byte, so
    /// the merged file can give every byte back unchanged (<see cref="TryWrite"/>).
    /// </summary>
    public static bool TryReadProgram(string path, [NotNullWhen(true)] out string? text, [NotNullWhen(false)] out string? error)
    {
        ArgumentNullException.ThrowIfNull(path);
        if (!AtomicFile.TryReadAll(path, MaxProgramBytes, out var bytes, out var reason))
        {
            (text, error) = (null, $"{path}: {reason}");
            return false;
        }

        (text, error) = (Encoding.Latin1.GetString(bytes), null);
        return true;
    }

    /// <summary>Writes <see cref="Files"/> into <paramref name="folder"/> (created when missing); stops at the first file that fails.</summary>
    public bool TryWrite(string folder, out ImmutableArray<string> written, [NotNullWhen(false)] out string? error)
    {
        ArgumentNullException.ThrowIfNull(folder);
        written = [];
        if (!Ok)
        {
            error = "nothing to write: the handler was refused or collides with the program";
            return false;
        }

        if (File.Exists(folder))
        {
            // Directory.CreateDirectory says only "already exists", which reads as if the folder were fine.
            error = $"{folder} is a file, not a folder: give the folder for the generated files";
            return false;
        }

        try
        {
            Directory.CreateDirectory(folder);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            error = $"cannot create the folder {folder}: {FileProblemText.Describe(ex, folder, FileAction.Write)}";
            return false;
        }

        var paths = new List<string>();
        foreach (var (name, text) in Files)
        {
            var path = Path.Combine(folder, name);
            if (!AtomicFile.TryWrite(path, Encoding.Latin1.GetBytes(text), out var failed))
            {
                (written, error) = ([.. paths], $"{path}: {failed}");
                return false;
            }

            paths.Add(path);
        }

        (written, error) = ([.. paths], null);
        return true;
    }
}
