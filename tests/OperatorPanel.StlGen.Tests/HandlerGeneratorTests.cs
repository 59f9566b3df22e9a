using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests;

public sealed class HandlerGeneratorTests
{
    private static readonly CpuProfile Cpu224 = CpuProfiles.For(CpuModel.Cpu224, CpuRevision.Current);

    [Fact]
    public void TryGenerateAwl_LineSettings_GivesTheSameTextAsGenerate()
    {
        var serial = new SerialSettings { PortName = "COM3", BaudRate = 19200, Parity = Parity.Even };
        var options = HandlerOptions.ForLine(Cpu224, 0, 17, 0x10, 9, serial);

        HandlerGenerator.TryGenerateAwl(options, out var text, out var error).Should().BeTrue();

        error.Should().BeNull();
        text.Should().Be(HandlerGenerator.Generate(options).AwlText);
        options.Should().Match<HandlerOptions>(o => o.BaudRate == 19200 && o.Parity == Parity.Even && o.Station == 17 && o.WriteMask == 0x10 && o.ReplyDelayMs == 9);
    }

    [Fact]
    public void TryGenerateAwl_PortTheCpuLacks_FalseWithTheDiagnostic()
    {
        var options = HandlerOptions.ForLine(Cpu224, 1, 2, 0x3C, 5, new SerialSettings { PortName = "COM3" });

        HandlerGenerator.TryGenerateAwl(options, out var text, out var error).Should().BeFalse();

        text.Should().BeNull();
        error.Should().StartWith("the handler cannot be generated: STL001");
    }
}
