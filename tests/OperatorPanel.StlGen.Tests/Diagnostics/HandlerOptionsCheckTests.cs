using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;
using OperatorPanel.StlGen.Diagnostics;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.Diagnostics;

public sealed class HandlerOptionsCheckTests
{
    private static readonly CpuProfile Cpu224 = CpuProfiles.For(CpuModel.Cpu224);

    public static TheoryData<string, HandlerOptions, string> BadSettings => new()
    {
        { StlDiagnostics.PortNotOnCpu, new HandlerOptions { Protocol = 2, Cpu = Cpu224, Port = 1 }, "port 1" },
        { StlDiagnostics.BaudNotAllowed, new HandlerOptions { Protocol = 2, Cpu = CpuProfiles.For(CpuModel.Cpu224, CpuRevision.Early), BaudRate = 115200 }, "115200" },
        { StlDiagnostics.DataBitsNotAllowed, new HandlerOptions { Protocol = 2, Cpu = Cpu224, DataBits = 6 }, "6 data bits" },
        { StlDiagnostics.StopBitsNotAllowed, new HandlerOptions { Protocol = 2, Cpu = Cpu224, StopBits = 2 }, "2 stop bits" },
        { StlDiagnostics.BufferOutsideV, new HandlerOptions { Protocol = 2, Cpu = Cpu224, BufferStart = 8000 }, "VB8000-VB8427" },
        { StlDiagnostics.BufferOutsideV, new HandlerOptions { Protocol = 3, Cpu = Cpu224, BufferStart = 2 }, "a protocol 3 handler starts at VB3 or later (its frame check points 3 bytes before its V bytes); allowed buffer start: VB3-VB7586" },
        { StlDiagnostics.DataBitsNotAllowed, new HandlerOptions { Protocol = 3, Cpu = Cpu224, DataBits = 7 }, "7 data bits: protocol 3 frames are binary bytes and need 8 data bits" },
        { StlDiagnostics.StationOutOfRange, new HandlerOptions { Protocol = 2, Cpu = Cpu224, Station = 127 }, "127" },
        { StlDiagnostics.ReplyDelayOutOfRange, new HandlerOptions { Protocol = 2, Cpu = Cpu224, ReplyDelayMs = 0 }, "reply delay 0 ms" },
        { StlDiagnostics.CharTimeoutOutOfRange, new HandlerOptions { Protocol = 2, Cpu = Cpu224, CharTimeoutMs = -1 }, "-1 ms" },
        { StlDiagnostics.SubroutineOutOfRange, new HandlerOptions { Protocol = 2, Cpu = Cpu224, FirstSubroutine = 64 }, "SBR64" },
        { StlDiagnostics.InterruptOutOfRange, new HandlerOptions { Protocol = 2, Cpu = Cpu224, FirstInterrupt = 126 }, "INT126-INT128" },
        { StlDiagnostics.InterruptOutOfRange, new HandlerOptions { Cpu = Cpu224, FirstInterrupt = 127 }, "INT127-INT128" },
        { StlDiagnostics.WriteMaskNotAllowed, new HandlerOptions { Protocol = 2, Cpu = Cpu224, WriteMask = 0x3E }, "16#3E" },
        { StlDiagnostics.BlockNameInvalid, new HandlerOptions { Protocol = 2, Cpu = Cpu224, Names = new HandlerBlockNames { Receive = "1RX" } }, "'1RX'" },
        { StlDiagnostics.BlockNamesOverlap, new HandlerOptions { Protocol = 2, Cpu = Cpu224, Names = new HandlerBlockNames { Delay = "OP_RX" } }, "'OP_RX'" },
        { StlDiagnostics.ParityNotAllowed, new HandlerOptions { Protocol = 2, Cpu = Cpu224, Parity = (Parity)7 }, "parity 7" },
        {
            StlDiagnostics.CompactHandlerHasNoStop, new HandlerOptions { Protocol = 3, Cpu = Cpu224, Compact = true, AllowStop = true },
            "station 1 has \"compact\": true and \"allowStop\": true, but a compact handler has no STOP"
        },
    };

    [Theory]
    [MemberData(nameof(BadSettings))]
    public void Check_BadSetting_ReportsItsIdNamingTheValue(string id, HandlerOptions options, string named)
    {
        var diagnostics = HandlerOptionsCheck.Check(options);

        diagnostics.Should().ContainSingle().Which.Should().Match<StlDiagnostic>(d => d.Id == id && d.Message.Contains(named, StringComparison.Ordinal));
    }

    [Theory]
    [MemberData(nameof(BadSettings))]
    public void Generate_BadSetting_ReturnsDiagnosticsAndNoText(string id, HandlerOptions options, string named)
    {
        var result = HandlerGenerator.Generate(options);

        result.Ok.Should().BeFalse();
        result.Diagnostics.Select(d => d.Id).Should().Equal(id);
        result.AwlText.Should().BeEmpty(named);
    }

    [Fact]
    public void Check_IdsAreDistinct_AndNumberedFromStl001()
    {
        var ids = typeof(StlDiagnostics).GetFields().Select(f => (string)f.GetValue(null)!).ToList();

        ids.Should().OnlyHaveUniqueItems().And.Contain("STL001").And.OnlyContain(id => id.StartsWith("STL", StringComparison.Ordinal));
    }

    [Theory]
    [InlineData(CpuModel.Cpu221, CpuRevision.Current, 1620)]
    [InlineData(CpuModel.Cpu224, CpuRevision.Early, 4692)]
    [InlineData(CpuModel.Cpu224, CpuRevision.Current, 7764)]
    [InlineData(CpuModel.Cpu226, CpuRevision.Current, 9812)]
    public void Defaults_BufferStart_EndsAtTheLastVByteEvenAligned(CpuModel model, CpuRevision revision, int start)
    {
        var cpu = CpuProfiles.For(model, revision);
        var options = new HandlerOptions { Protocol = 2, Cpu = cpu };

        options.EffectiveBufferStart.Should().Be(start);
        HandlerOptionsCheck.Check(options).Should().BeEmpty();
    }

    [Theory]
    [InlineData(CpuModel.Cpu224, 63)]
    [InlineData(CpuModel.Cpu226, 127)]
    public void Defaults_Blocks_AreAtTheTopOfTheRanges(CpuModel model, int sbr)
    {
        var options = new HandlerOptions { Protocol = 2, Cpu = CpuProfiles.For(model) };

        options.EffectiveFirstSubroutine.Should().Be(sbr);
        options.EffectiveFirstInterrupt.Should().Be(125);
    }

    [Fact]
    public void Check_Protocol3HandlerInTheLastTwoInterruptRoutines_IsAccepted()
    {
        var options = new HandlerOptions { Cpu = Cpu224, FirstInterrupt = 126 };

        HandlerOptionsCheck.Check(options).Should().BeEmpty("protocol 3 takes two interrupt routines: INT126 and INT127");
        HandlerGenerator.Generate(options).Stats!.Blocks.Select(b => b.NumberText).Should().Equal("SBR63", "INT126", "INT127");
    }
}
