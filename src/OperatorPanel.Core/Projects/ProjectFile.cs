using System.Collections.Immutable;
using System.Diagnostics.CodeAnalysis;
using System.Globalization;
using System.Text;
using System.Text.Json;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// Reads and writes <c>.opproj</c> project files (one JSON file per production line). Loading never throws on bad
/// input: every problem comes back with its location. Saving is atomic and keeps the previous file as <c>.bak</c>.
/// </summary>
public static class ProjectFile
{
    public const string Extension = ".opproj";

    /// <summary>The file schema this program reads and writes (<c>"schemaVersion"</c>).</summary>
    public const int SchemaVersion = 1;

    /// <summary>Larger files are refused unread; a line with every address of a CPU 226 symbolised is under 1 MiB.</summary>
    public const long MaxFileBytes = 16 * 1024 * 1024;

    private static readonly UTF8Encoding StrictUtf8 = new(encoderShouldEmitUTF8Identifier: false, throwOnInvalidBytes: true);

    /// <summary>Loads the project file at <paramref name="path"/>; a missing or unreadable file is a problem at "file".</summary>
    public static ProjectLoadResult Load(string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        if (!AtomicFile.TryReadAll(path, MaxFileBytes, out var bytes, out var readError))
        {
            return Fail("file", readError);
        }

        if (bytes.Length == 0)
        {
            return Fail("file", "the file is empty (0 bytes); a project file is JSON text starting with '{'");
        }

        string text;
        try
        {
            text = StrictUtf8.GetString(bytes);
        }
        catch (DecoderFallbackException ex)
        {
            return Fail("file", string.Create(CultureInfo.InvariantCulture, $"not UTF-8 text (invalid byte at offset {ex.Index}); is this a project file?"));
        }

        return Parse(text);
    }

    /// <summary>Reads project text; every problem is collected, none thrown.</summary>
    public static ProjectLoadResult Parse(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        text = text.TrimStart('\uFEFF');
        JsonDocument document;
        try
        {
            document = JsonDocument.Parse(text);
        }
        catch (JsonException ex)
        {
            return Fail(SyntaxLocation(text, ex), "not valid JSON: " + JsonSyntaxText.Describe(text, ex));
        }

        using (document)
        {
            var problems = new ProjectProblems();
            var project = ProjectReader.Read(document.RootElement, problems);
            return project is not null && problems.Count == 0
                ? ProjectLoadResult.Success(project)
                : ProjectLoadResult.Failure(problems.ToImmutable());
        }
    }

    /// <summary>The file text for <paramref name="project"/>: indented JSON, stable property order, LF line ends.</summary>
    public static string Format(PanelProject project) => ProjectWriter.WriteText(project);

    /// <summary>Problems a project built in code would show once saved (paths as in the saved file); empty when valid.</summary>
    public static ImmutableArray<ProjectFileError> Check(PanelProject project)
    {
        var result = Parse(Format(project));
        return result.Ok ? [] : result.Errors;
    }

    /// <summary>
    /// Writes <paramref name="project"/> to <paramref name="path"/> atomically: a temporary file in the same folder is
    /// written and flushed to disk, then replaces the target, whose previous content is kept as <c>path.bak</c>.
    /// A failure (no such folder, access denied, disk full) leaves the target as it was; a read-only target or folder,
    /// or a target that cannot be opened for writing, is refused before anything is written, its .bak untouched.
    /// </summary>
    public static bool TrySave(PanelProject project, string path, [NotNullWhen(false)] out string? error)
    {
        ArgumentNullException.ThrowIfNull(project);
        ArgumentNullException.ThrowIfNull(path);
        return AtomicFile.TryWrite(path, ProjectWriter.Write(project), out error);
    }

    private static ProjectLoadResult Fail(string location, string message) =>
        ProjectLoadResult.Failure([new ProjectFileError(location, message)]);

    /// <summary>"line 5, column 12", 1-based; System.Text.Json counts bytes within the line, the editor counts characters.</summary>
    private static string SyntaxLocation(string text, JsonException ex)
    {
        var lineIndex = (int)Math.Clamp(ex.LineNumber ?? 0, 0, int.MaxValue);
        var lines = text.Split('\n');
        var line = lineIndex < lines.Length ? lines[lineIndex] : string.Empty;
        var bytes = Encoding.UTF8.GetBytes(line);
        var byteColumn = (int)Math.Clamp(ex.BytePositionInLine ?? 0, 0, bytes.Length);
        var column = Encoding.UTF8.GetCharCount(bytes, 0, byteColumn) + 1;
        return string.Create(CultureInfo.InvariantCulture, $"line {lineIndex + 1}, column {column}");
    }
}
