using System.Collections.Immutable;
using OperatorPanel.Stl;
using OperatorPanel.Stl.Checks;
using OperatorPanel.StlGen.Diagnostics;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Merge;

/// <summary>
/// Adds the handler to a program the user exported from Micro/WIN (File &gt; Export): checks for collisions first
/// (block numbers and names, interrupt events, the port, its special memory, SMB34, V bytes) and writes one combined
/// .awl only when there are none. What Micro/WIN itself would refuse in the user's program (Core AwlProgramCheck) is an
/// error too. Warnings (what the text alone cannot show) do not stop the merge.
/// </summary>
public static class HandlerMerger
{
    public static MergeResult Merge(string userText, HandlerOptions options)
    {
        ArgumentNullException.ThrowIfNull(userText);
        ArgumentNullException.ThrowIfNull(options);
        var settings = HandlerOptionsCheck.Check(options);
        if (!settings.IsEmpty)
        {
            return Failed(settings.Select(d => new MergeDiagnostic(d.Id, MergeSeverity.Error, 0, d.Message)));
        }

        var parsed = AwlParser.Parse(userText);
        if (!parsed.Succeeded)
        {
            return Failed(parsed.Diagnostics.Select(d => new MergeDiagnostic(
                StlDiagnostics.UserProgramInvalid, MergeSeverity.Error, d.Line, $"the user's program does not parse: {d.Message}; nothing was written")));
        }

        var user = parsed.Program;
        if (user.MainBlock is null)
        {
            return Failed([new MergeDiagnostic(StlDiagnostics.UserProgramHasNoMain, MergeSeverity.Error, 1, "the user's program has no ORGANIZATION_BLOCK (OB1) to call the handler from; export the whole program block from Micro/WIN")]);
        }

        var cpu = options.Cpu;
        var handler = new HandlerFootprint(options);
        var found = AwlProgramCheck.Check(user, cpu).Select(d => new MergeDiagnostic(
            StlDiagnostics.UserProgramRefused, MergeSeverity.Error, d.Line, $"Micro/WIN refuses the user's program here ({d.Id}): {d.Message}")).ToList();
        found.AddRange(BlockCollisions.Find(user, handler, cpu.Subroutines, cpu.InterruptRoutines));
        found.AddRange(new InstructionCollisions(user, handler, cpu.CommunicationPorts, HandlerDefaults.VBytes(cpu)).Find());
        var lines = MergedProgramWriter.SplitLines(userText);
        var ordered = found.OrderBy(d => d.Line).ThenBy(d => d.Id, StringComparer.Ordinal).ToImmutableArray();
        if (ordered.Any(d => d.Severity == MergeSeverity.Error))
        {
            return new MergeResult(ordered, string.Empty);
        }

        var generated = HandlerGenerator.Generate(options);
        return new MergeResult(ordered, MergedProgramWriter.Write(lines, user, generated.AwlText));
    }

    private static MergeResult Failed(IEnumerable<MergeDiagnostic> diagnostics) => new([.. diagnostics], string.Empty);
}
