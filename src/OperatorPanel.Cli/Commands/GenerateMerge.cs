using System.Text;
using OperatorPanel.StlGen.Merge;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// The --merge part of <c>opanel generate</c>: reads the user's exported program and merges the handler into it.
/// Collisions print as <c>USER.awl:57: STL022 ...</c> (the compiler's file:line form, so editors jump to the line) and
/// stop everything; warnings print the same way with "warning" and do not.
/// </summary>
internal static class GenerateMerge
{
    /// <summary>Null when the merged text is ready (warnings already printed); otherwise the exit code, reported.</summary>
    public static int? TryMerge(CliContext cli, string userPath, HandlerOptions options, out string merged, out IReadOnlyList<MergeDiagnostic> warnings)
    {
        merged = string.Empty;
        warnings = [];
        string text;
        try
        {
            // Micro/WIN exports in the Windows ANSI code page: Latin-1 keeps one character per byte, and the merger
            // writes anything outside ASCII as '?' with a warning.
            text = File.ReadAllText(userPath, Encoding.Latin1);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            return cli.Fail(ExitCodes.BadInput, $"cannot read {userPath}: {ex.Message}");
        }

        var result = HandlerMerger.Merge(text, options);
        var name = Path.GetFileName(userPath);
        if (!result.Ok)
        {
            if (cli.Json)
            {
                cli.WriteJson(new { ok = false, diagnostics = result.Diagnostics.Select(d => Json(name, d)) });
            }
            else
            {
                foreach (var diagnostic in result.Diagnostics)
                {
                    cli.Error.WriteLine(Format(name, diagnostic));
                }

                cli.Error.WriteLine($"opanel: nothing written: the handler collides with {name}");
            }

            return ExitCodes.GeneratorRefused;
        }

        if (!cli.Json)
        {
            foreach (var warning in result.Warnings)
            {
                cli.Error.WriteLine(Format(name, warning));
            }
        }

        merged = result.MergedText;
        warnings = [.. result.Warnings];
        return null;
    }

    public static object Json(string file, MergeDiagnostic d) =>
        new { file, line = d.Line, id = d.Id, severity = d.Severity.ToString().ToLowerInvariant(), message = d.Message };

    /// <summary>"USER.awl:57: STL022 VW8000 ..." or "USER.awl:12: warning STL025 ..."; a setting without a line: "opanel: STL001 ...".</summary>
    private static string Format(string file, MergeDiagnostic d)
    {
        var where = d.Line > 0 ? $"{file}:{d.Line}" : "opanel";
        var kind = d.Severity == MergeSeverity.Warning ? "warning " : string.Empty;
        return $"{where}: {kind}{d.Id} {d.Message}";
    }
}
