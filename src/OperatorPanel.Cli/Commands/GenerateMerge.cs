using OperatorPanel.StlGen.Merge;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// How <c>opanel generate --merge</c> reports the merge of the handler package (StlGen HandlerPackage). Collisions
/// print as <c>USER.awl:57: STL022 ...</c> (the compiler's file:line form, so editors jump to the line) and stop
/// everything; warnings print the same way with "warning" and do not.
/// </summary>
internal static class GenerateMerge
{
    /// <summary>Prints the findings; returns the warnings as JSON objects for the final output (printed on stderr already in text mode).</summary>
    public static List<object> Report(CliContext cli, string name, MergeResult result)
    {
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

                cli.Error.WriteLine($"opanel: nothing written: the merge with {name} was refused ({result.Errors.Count()} problem(s))");
            }

            return [];
        }

        if (!cli.Json)
        {
            foreach (var warning in result.Warnings)
            {
                cli.Error.WriteLine(Format(name, warning));
            }
        }

        return [.. result.Warnings.Select(w => Json(name, w))];
    }

    private static object Json(string file, MergeDiagnostic d) =>
        new { file, line = d.Line, id = d.Id, severity = d.Severity.ToString().ToLowerInvariant(), message = d.Message };

    /// <summary>"USER.awl:57: STL022 VW8000 ..." or "USER.awl:12: warning STL025 ..."; a setting without a line: "opanel: STL001 ...".</summary>
    private static string Format(string file, MergeDiagnostic d)
    {
        var where = d.Line > 0 ? $"{file}:{d.Line}" : "opanel";
        var kind = d.Severity == MergeSeverity.Warning ? "warning " : string.Empty;
        return $"{where}: {kind}{d.Id} {d.Message}";
    }
}
