using System.Text;
using OperatorPanel.Stl;
using OperatorPanel.StlGen.Tests.Merge.UserPrograms;

namespace OperatorPanel.StlGen.Tests;

public sealed class HandlerPackageTests : IDisposable
{
    private readonly string _folder = Path.Combine(Path.GetTempPath(), "opanel-package-" + Guid.NewGuid().ToString("N"));

    public void Dispose()
    {
        if (Directory.Exists(_folder))
        {
            Directory.Delete(_folder, recursive: true);
        }
    }

    [Fact]
    public void Generate_WithUserProgram_WritesHandlerSymbolsNotesAndMergedUnderTheStem()
    {
        var package = HandlerPackage.Generate(UserProgram.Cpu224, "Filler", AwlSource.FromText(UserProgram.Ob1("LD     SM0.0", "=      Q0.0")));

        package.TryWrite(_folder, out var written, out var error).Should().BeTrue(error);

        written.Select(Path.GetFileName).Should().Equal("Filler-handler.awl", "Filler-symbols.txt", "Filler-README.txt", "Filler-merged.awl");
        File.ReadAllText(Path.Combine(_folder, "Filler-merged.awl")).Should().Be(package.Merge!.MergedText);
        File.ReadAllText(Path.Combine(_folder, "Filler-handler.awl")).Should().Be(package.Handler.AwlText);
    }

    [Fact]
    public void TryWrite_UserProgramInTheWindowsCodePage_MergedFileKeepsItsBytes()
    {
        byte[] comment = [0x2F, 0x2F, 0x20, 0x46, 0xFC, 0x6C, 0x6C, 0x73, 0x74, 0x61, 0x6E, 0x64];
        var user = UserProgram.Ob1("LD     SM0.0 " + Encoding.Latin1.GetString(comment), "=      Q0.0");
        var package = HandlerPackage.Generate(UserProgram.Cpu224, "Filler", AwlSource.FromText(user));

        package.TryWrite(_folder, out _, out var error).Should().BeTrue(error);

        var merged = File.ReadAllBytes(Path.Combine(_folder, "Filler-merged.awl"));
        byte[] line = [.. Encoding.ASCII.GetBytes("LD     SM0.0 "), .. comment, 0x0D, 0x0A];
        merged.AsSpan().IndexOf(line).Should().BeGreaterThan(0, "the user's line is written back byte for byte (0xFC is u-umlaut in code page 1252)");
    }

    [Fact]
    public void Generate_ProgramCollides_NothingToWriteAndTheFolderIsNotCreated()
    {
        var package = HandlerPackage.Generate(UserProgram.Cpu224, "Filler", AwlSource.FromText(UserProgram.Ob1("LD     SM0.0", "MOVB   1, VB8000")));

        package.Ok.Should().BeFalse();
        package.Files.Should().BeEmpty();
        package.TryWrite(_folder, out _, out var error).Should().BeFalse();
        error.Should().StartWith("nothing to write");
        Directory.Exists(_folder).Should().BeFalse();
    }

    [Fact]
    public void TryReadProgram_FileAboveTheLimit_RefusedNamingTheFile()
    {
        Directory.CreateDirectory(_folder);
        var path = Path.Combine(_folder, "huge.awl");
        File.WriteAllBytes(path, new byte[HandlerPackage.MaxProgramBytes + 1]);

        HandlerPackage.TryReadProgram(path, out var text, out var error).Should().BeFalse();

        text.Should().BeNull();
        error.Should().StartWith($"cannot read {path}: ");
    }

    [Fact]
    public void TryReadProgram_WindowsCodePageBytes_DecodedAsCodePage1252AndKept()
    {
        Directory.CreateDirectory(_folder);
        var path = Path.Combine(_folder, "user.awl");
        File.WriteAllBytes(path, [0x4C, 0x44, 0x20, 0xE4]);

        HandlerPackage.TryReadProgram(path, out var program, out _).Should().BeTrue();

        program!.Text.Should().Be("LD ä");
        program.Kind.Should().Be(AwlTextEncoding.Windows1252);
        program.Bytes.Should().Equal(0x4C, 0x44, 0x20, 0xE4);
    }
}
