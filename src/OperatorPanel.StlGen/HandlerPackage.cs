using System.Collections.Immutable;
using System.Diagnostics.CodeAnalysis;
using System.Globalization;
using System.Text;
using OperatorPanel.Core.Messages;
using OperatorPanel.Core.Projects;
using OperatorPanel.Stl;
using OperatorPanel.Stl.Symbols;
using OperatorPanel.StlGen.Merge;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen;

/// <summary>
/// What Generate PLC code and <c>opanel generate</c> save for one station, decided once for both: the handler
/// (<see cref="HandlerGenerator"/>), merged into the user's exported program when one is given (<see cref="HandlerMerger"/>),
/// the file names (STEM-handler.awl, STEM-symbols.txt, STEM-README.txt, STEM-merged.awl), the size limit of the user's
/// program and the writing (each file atomically: the generated text is ASCII, the user's lines in the merged file go
/// back in the bytes they came in).
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

    /// <summary>The files to save, name and content; empty unless <see cref="Ok"/>.</summary>
    public ImmutableArray<(string Name, byte[] Content)> Files => !Ok ? [] :
    [
        ($"{Stem}-handler.awl", Encoding.ASCII.GetBytes(Handler.AwlText)),
        ($"{Stem}-symbols.txt", Encoding.ASCII.GetBytes(Handler.SymbolTableText)),
        ($"{Stem}-README.txt", Encoding.ASCII.GetBytes(Handler.TechnicianText)),
        .. Merge is { } merge ? [($"{Stem}-merged.awl", merge.MergedBytes)] : Array.Empty<(string, byte[])>(),
    ];

    /// <summary>A station name as part of a file name: letters, digits, '-' and '_' kept, anything else '_'.</summary>
    public static string FileStem(ProjectStation station)
    {
        ArgumentNullException.ThrowIfNull(station);
        var chars = station.Name.Select(c => char.IsAsciiLetterOrDigit(c) || c is '-' or '_' ? c : '_').ToArray();
        return chars.Length == 0 ? "station" + station.Address.Address.ToString(CultureInfo.InvariantCulture) : new string(chars);
    }

    /// <summary>
    /// Generates the handler for <paramref name="options"/> and, with <paramref name="userProgram"/>, merges it in (its
    /// symbolic operands resolved by <paramref name="symbols"/> when given).
    /// </summary>
    public static HandlerPackage Generate(HandlerOptions options, string stem, AwlSource? userProgram = null, AwlSymbolTable? symbols = null)
    {
        ArgumentNullException.ThrowIfNull(options);
        ArgumentException.ThrowIfNullOrWhiteSpace(stem);
        var handler = HandlerGenerator.Generate(options);
        var merge = handler.Ok && userProgram is not null ? HandlerMerger.Merge(userProgram, options, symbols) : null;
        return new HandlerPackage(stem, handler, merge);
    }

    /// <summary>
    /// <see cref="Generate"/> with the user's program read from <paramref name="programPath"/> when one is given; false
    /// with the reason when the file cannot be read.
    /// </summary>
    public static bool TryGenerate(
        HandlerOptions options, string stem, string? programPath, [NotNullWhen(true)] out HandlerPackage? package, [NotNullWhen(false)] out string? error)
    {
        AwlSource? program = null;
        if (programPath is not null && !TryReadProgram(programPath, out program, out error))
        {
            package = null;
            return false;
        }

        (package, error) = (Generate(options, stem, program), null);
        return true;
    }

    /// <summary>
    /// Reads a program exported from Micro/WIN: its encoding is detected (<see cref="AwlSource"/>) for the diagnostics,
    /// and its bytes are kept, so the merged file gives every one of them back unchanged (<see cref="TryWrite"/>).
    /// </summary>
    public static bool TryReadProgram(string path, [NotNullWhen(true)] out AwlSource? program, [NotNullWhen(false)] out string? error)
    {
        ArgumentNullException.ThrowIfNull(path);
        if (!AtomicFile.TryReadAll(path, MaxProgramBytes, out var bytes, out var reason))
        {
            (program, error) = (null, $"{path}: {reason}");
            return false;
        }

        (program, error) = (AwlSource.Decode(bytes), null);
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

        // A file name taken by a folder fails its save after the files before it were replaced: refuse before writing any.
        if (Files.Select(f => Path.Combine(folder, f.Name)).FirstOrDefault(Directory.Exists) is { } taken)
        {
            error = $"{taken} is a folder, not a file: move or rename it; nothing was written";
            return false;
        }

        var paths = new List<string>();
        foreach (var (name, content) in Files)
        {
            var path = Path.Combine(folder, name);
            if (!AtomicFile.TryWrite(path, content, out var failed))
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
