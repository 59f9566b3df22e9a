using System.Collections.Immutable;
using System.Text;
using OperatorPanel.Stl;
using OperatorPanel.Stl.Checks;
using OperatorPanel.Stl.Symbols;
using OperatorPanel.StlGen.Diagnostics;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Merge;

/// <summary>
/// Adds the handler to a program the user exported from Micro/WIN (File &gt; Export): checks for collisions first
/// (block numbers and names, interrupt events, the port, its special memory, SMB34, V bytes) and writes one combined
/// .awl only when there are none. What Micro/WIN itself would refuse in the user's program (Stl AwlProgramCheck and
/// AwlExportCheck: an unknown instruction, an OB1 header without its name, a CALL to a block the file does not hold ...)
/// is an error too. Warnings (what the text alone cannot show, a block exported without body) do not stop the merge.
/// The user's bytes go back unchanged whatever their code page; diagnostics use the decoded text.
/// </summary>
public static class HandlerMerger
{
    /// <summary>A program given as text: characters up to 255 are its bytes (<see cref="AwlSource.FromText"/>).</summary>
    public static MergeResult Merge(string userText, HandlerOptions options)
    {
        ArgumentNullException.ThrowIfNull(userText);
        return Merge(AwlSource.FromText(userText), options);
    }

    /// <summary>Merges a program read from a file; with <paramref name="symbols"/> its symbolic operands are checked as the addresses they stand for.</summary>
    public static MergeResult Merge(AwlSource user, HandlerOptions options, AwlSymbolTable? symbols = null)
    {
        ArgumentNullException.ThrowIfNull(user);
        ArgumentNullException.ThrowIfNull(options);
        var settings = HandlerOptionsCheck.Check(options);
        if (!settings.IsEmpty)
        {
            return Failed(settings.Select(d => new MergeDiagnostic(d.Id, MergeSeverity.Error, 0, d.Message)));
        }

        if (user.HasByteOrderMark)
        {
            return Failed([new MergeDiagnostic(StlDiagnostics.UserProgramInvalid, MergeSeverity.Error, 1,
                "the file starts with a UTF-8 byte order mark (EF BB BF); Micro/WIN imports a file in the Windows code page without one: save it as ANSI; nothing was written")]);
        }

        var parsed = AwlParser.Parse(user.Text);
        if (!parsed.Succeeded)
        {
            return Failed(parsed.Diagnostics.Select(d => new MergeDiagnostic(
                StlDiagnostics.UserProgramInvalid, MergeSeverity.Error, d.Line, $"the user's program does not parse: {d.Message}; nothing was written")));
        }

        var program = parsed.Program;
        if (program.MainBlock is null)
        {
            return Failed([new MergeDiagnostic(StlDiagnostics.UserProgramHasNoMain, MergeSeverity.Error, 1, "the user's program has no ORGANIZATION_BLOCK (OB1) to call the handler from; export the whole program block from Micro/WIN")]);
        }

        var found = new List<MergeDiagnostic>();
        if (symbols is not null)
        {
            (program, var unknown) = AwlSymbolResolver.Resolve(program, symbols);
            found.AddRange(unknown.Select(d => new MergeDiagnostic(StlDiagnostics.SymbolNotInTable, MergeSeverity.Error, d.Line, d.Message)));
        }

        var cpu = options.Cpu;
        var export = AwlExportCheck.Check(program);
        found.AddRange(export.Refusals.Concat(AwlProgramCheck.Check(program, cpu)).Select(d => new MergeDiagnostic(
            StlDiagnostics.UserProgramRefused, MergeSeverity.Error, d.Line, $"Micro/WIN refuses the user's program here ({d.Id}): {d.Message}")));
        var handler = new HandlerFootprint(options);
        found.AddRange(ProtectedBlocks.Find(program, handler, cpu.CommunicationPorts));
        found.AddRange(BlockCollisions.Find(program, handler, cpu.Subroutines, cpu.InterruptRoutines));
        found.AddRange(new InstructionCollisions(program, handler, cpu.CommunicationPorts, HandlerDefaults.VBytes(cpu)).Find());
        var ordered = found.OrderBy(d => d.Line).ThenBy(d => d.Id, StringComparer.Ordinal).ToImmutableArray();
        if (ordered.Any(d => d.Severity == MergeSeverity.Error))
        {
            return new MergeResult(ordered, string.Empty);
        }

        var generated = HandlerGenerator.Generate(options);
        var merged = Encoding.Latin1.GetBytes(MergedProgramWriter.Write(MergedProgramWriter.SplitLines(user.ByteText), parsed.Program, generated.AwlText));
        return new MergeResult(ordered, user.Encoding.GetString(merged)) { MergedBytes = merged };
    }

    private static MergeResult Failed(IEnumerable<MergeDiagnostic> diagnostics) => new([.. diagnostics], string.Empty);
}
