using System.Runtime.CompilerServices;
using System.Text;
using OperatorPanel.Stl;
using OperatorPanel.Stl.Symbols;
using OperatorPanel.StlGen.Diagnostics;
using OperatorPanel.StlGen.Merge;
using OperatorPanel.StlGen.Tests.Merge.UserPrograms;

namespace OperatorPanel.StlGen.Tests.Merge;

/// <summary>
/// The merge on the export forms of tests/StlCorpus: what Micro/WIN refuses is refused with line and rule, a protected
/// POU is a warning, every code page goes back byte for byte with its names read in diagnostics, and symbols are
/// checked as their addresses with the program's symbol table.
/// </summary>
public sealed class HandlerMergerExportFormTests
{
    [Theory]
    [InlineData("Ob1WithoutName.awl", 1, "(AWL012): the header of OB1 has no name")]
    [InlineData("CallMissing.awl", 6, "(AWL013): CALL VALVES: the file has no subroutine of that name")]
    [InlineData("SubroutineTwice.awl", 13, "(AWL014): SBR_0 is defined twice in the file")]
    public void Merge_WhatMicroWinRefuses_RefusedWithLineAndRule(string name, int line, string reason)
    {
        var result = HandlerMerger.Merge(Corpus("MicroWinRefuses", name), UserProgram.Cpu224);

        result.Ok.Should().BeFalse();
        result.MergedBytes.Should().BeEmpty();
        result.Errors.Should().ContainSingle().Which.Should().Match<MergeDiagnostic>(d =>
            d.Id == StlDiagnostics.UserProgramRefused && d.Line == line && d.Message.Contains(reason, StringComparison.Ordinal));
    }

    [Fact]
    public void Merge_ProtectedPou_WarnsNamingItAndMerges()
    {
        var result = HandlerMerger.Merge(Corpus("ProtectedPou.awl"), UserProgram.Cpu224);

        result.Ok.Should().BeTrue();
        result.Warnings.Should().ContainSingle().Which.Should().Match<MergeDiagnostic>(d =>
            d.Id == StlDiagnostics.UserBlockWithoutBody && d.Line == 16 && d.Message.StartsWith("PWM_INIT (SBR0, line 16) is password-protected: the export holds none of its code, so the handler's port 0, interrupt events 23, 10, 9 and VB7764-VB8191 cannot be checked against it", StringComparison.Ordinal));
    }

    [Theory]
    [InlineData("Cp1252.awl", "Zähler")]
    [InlineData("Gbk.awl", "计数")]
    [InlineData("Utf8.awl", "Zähler")]
    public void Merge_CodePages_UserBytesBackUnchangedAndNamesRead(string name, string subroutine)
    {
        var user = Corpus("Encodings", name);

        var result = HandlerMerger.Merge(user, UserProgram.Cpu224);

        result.Ok.Should().BeTrue(string.Join("; ", result.Diagnostics));
        var merged = Lines(result.MergedBytes);
        var position = 0;
        foreach (var line in Lines(user.Bytes))
        {
            var renumbered = line.StartsWith("Network 1 ", StringComparison.Ordinal) && position < 8 ? "Network 2 " + line[10..] : line;
            position = merged.IndexOf(renumbered, position);
            position.Should().BeGreaterThanOrEqualTo(0, $"'{line}' (its bytes) is in the merged file, in order");
        }

        result.MergedText.Should().Contain($"SUBROUTINE_BLOCK {subroutine}:SBR0");
    }

    [Fact]
    public void Merge_CodePage_NameOfAMissingBlockReadInTheDiagnostic()
    {
        var gbk = Corpus("Encodings", "Gbk.awl");
        var user = AwlSource.Decode(gbk.Encoding.GetBytes(gbk.Text.Replace("CALL   计数", "CALL   计时", StringComparison.Ordinal)));

        var result = HandlerMerger.Merge(user, UserProgram.Cpu224);

        result.Errors.Should().ContainSingle().Which.Message.Should().Contain("CALL 计时: the file has no subroutine");
    }

    [Fact]
    public void Merge_Utf8ByteOrderMark_RefusedAsMicroWinWould()
    {
        var result = HandlerMerger.Merge(Corpus("Encodings", "Utf8Bom.awl"), UserProgram.Cpu224);

        result.Errors.Should().ContainSingle().Which.Should().Match<MergeDiagnostic>(d => d.Line == 1 && d.Message.StartsWith("the file starts with a UTF-8 byte order mark", StringComparison.Ordinal));
    }

    [Fact]
    public void Merge_SymbolsWithTheirTable_CheckedAsTheirAddresses()
    {
        var symbols = AwlSymbolTable.Parse(Encoding.ASCII.GetString(Corpus("Symbols", "Conveyor-symbols.txt").Bytes));

        var plain = HandlerMerger.Merge(Corpus("Symbols", "Conveyor.awl"), UserProgram.Cpu224);
        var resolved = HandlerMerger.Merge(Corpus("Symbols", "Conveyor.awl"), UserProgram.Cpu224, symbols);

        plain.Warnings.Should().Contain(d => d.Id == StlDiagnostics.SymbolUnchecked, "without the table the symbols cannot be checked");
        resolved.Ok.Should().BeTrue();
        resolved.Warnings.Should().NotContain(d => d.Id == StlDiagnostics.SymbolUnchecked);
        resolved.MergedBytes.Should().Equal(plain.MergedBytes, "the user's lines go back as written, symbols and all");
    }

    [Fact]
    public void Merge_SymbolOnTheHandlersBytes_CollisionFoundThroughTheTable()
    {
        var symbols = AwlSymbolTable.Parse("Count\tVB8000\r\n");

        var result = HandlerMerger.Merge(AwlSource.FromText(UserProgram.Ob1("LD     SM0.0", "INCB   Count")), UserProgram.Cpu224, symbols);

        result.Errors.Should().ContainSingle().Which.Id.Should().Be(StlDiagnostics.VMemoryOverlap);
    }

    [Fact]
    public void Merge_SymbolNotInTheTable_RefusedNamingLineAndSymbol()
    {
        var symbols = AwlSymbolTable.Parse("Other\tVB10\r\n");

        var result = HandlerMerger.Merge(AwlSource.FromText(UserProgram.Ob1("LD     SM0.0", "INCB   Count")), UserProgram.Cpu224, symbols);

        result.Errors.Should().ContainSingle().Which.Should().Match<MergeDiagnostic>(d =>
            d.Id == StlDiagnostics.SymbolNotInTable && d.Line == UserProgram.FirstInstructionLine + 1 && d.Message == "INCB: symbol 'Count' is not in the symbol table");
    }

    private static List<string> Lines(byte[] bytes) => [.. Encoding.Latin1.GetString(bytes).Split("\r\n")];

    private static AwlSource Corpus(params string[] path) => AwlSource.Decode(File.ReadAllBytes(Path.Combine([CorpusFolder(), .. path])));

    private static string CorpusFolder([CallerFilePath] string self = "") =>
        Path.GetFullPath(Path.Combine(Path.GetDirectoryName(self)!, "..", "..", "StlCorpus"));
}
