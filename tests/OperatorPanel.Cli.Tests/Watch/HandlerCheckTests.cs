using OperatorPanel.Cli.Watch;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Tests.Watch;

/// <summary>The "handler" line of watch: a PLC whose handler was generated for another CPU than the project says is named.</summary>
public sealed class HandlerCheckTests
{
    private static readonly Station Two = new(2);

    [Fact]
    public void Describe_Cpu224HandlerInAProjectSaying226_IsAMismatchNamingBothAndTheFix()
    {
        var station = StationOf(CpuModel.Cpu226);

        var text = HandlerCheck.Describe(station, Identify(CpuModel.Cpu224, smb6: 0x20, modeSwitchRun: true));

        text.Should().Be("MISMATCH with CPU 226: the PLC reports SMB6 16#20 (CPU 224 or CPU 224XP), CPU 226 has 16#90; "
            + "the handler was generated for CPU 224, not CPU 226: regenerate it");
    }

    [Fact]
    public void Describe_MatchingHandler_IsOkWithProtocolAndModeSwitch()
    {
        var text = HandlerCheck.Describe(StationOf(CpuModel.Cpu224), Identify(CpuModel.Cpu224, smb6: 0x20, modeSwitchRun: true));

        text.Should().Be("ok: generated for CPU 224, protocol 2, mode switch RUN");
    }

    [Fact]
    public void Describe_V3Handlers_NameTheirShape()
    {
        var station = StationOf(CpuModel.Cpu224);
        var full = new Core.Protocol.V3.Identity(1, HandlerIdentity.CpuModelCode(CpuModel.Cpu224), 1, 0x1C, 0x03, 4, 0, 137, 16, 32, 128, 7586, 606, 0x20, 1, 3, 2, 9);
        var compact = full with { Features = 0, MaxRequestBytes = 137, ListItems = 0, ListBytes = 0, VFirst = 8014, VBytes = 178, StatusFlags = 0 };

        HandlerCheck.Describe(station, V3Link.AsIdentifyResponse(Two, full)).Should().Be("ok: generated for CPU 224, protocol 3, full handler (list of 32 items, 128 bytes, STOP), mode switch RUN");
        HandlerCheck.Describe(station with { Compact = true }, V3Link.AsIdentifyResponse(Two, compact)).Should().Be("ok: generated for CPU 224, protocol 3, compact handler (no list: READs of 16 bytes), mode switch TERM");
    }

    [Fact]
    public void Describe_CompactHandlerInAProjectSayingFull_NamesBothRangesAndTheFix()
    {
        var compact = Full with { Features = 0, ListItems = 0, ListBytes = 0, VFirst = 8014, VBytes = 178 };

        HandlerCheck.Describe(StationOf(CpuModel.Cpu224), V3Link.AsIdentifyResponse(Two, compact)).Should().Be(
            "ok: generated for CPU 224, protocol 3, compact handler (no list: READs of 16 bytes), mode switch RUN; but its V bytes are "
            + "VB8014-VB8191 and the project's VB7586-VB8191 (the bytes the panel refuses to write): set \"handlerVFirst\": 8014 and "
            + "\"compact\": true in the project, or regenerate the handler from it");
    }

    [Fact]
    public void Describe_HandlerGeneratedAtVB1000_WithoutTheProjectSayingSo_NamesTheProperty()
    {
        var moved = Full with { VFirst = 1000 };

        HandlerCheck.Describe(StationOf(CpuModel.Cpu224), V3Link.AsIdentifyResponse(Two, moved)).Should().EndWith(
            "; but its V bytes are VB1000-VB1605 and the project's VB7586-VB8191 (the bytes the panel refuses to write): "
            + "set \"handlerVFirst\": 1000 in the project, or regenerate the handler from it");
        HandlerCheck.Describe(StationOf(CpuModel.Cpu224) with { HandlerVFirst = 1000 }, V3Link.AsIdentifyResponse(Two, moved)).Should().Be(
            "ok: generated for CPU 224, protocol 3, full handler (list of 32 items, 128 bytes, STOP), mode switch RUN", "the project says where it is");
    }

    private static readonly Core.Protocol.V3.Identity Full =
        new(1, HandlerIdentity.CpuModelCode(CpuModel.Cpu224), 1, 0x1C, 0x03, 4, 0, 137, 16, 32, 128, 7586, 606, 0x20, 1, 3, 2, 9);

    [Fact]
    public void Describe_ErrorReplyToIdentify_SaysRegenerate()
    {
        var text = HandlerCheck.Describe(StationOf(CpuModel.Cpu224), new ErrorResponse(Two, 1, CommandCode.Identify, ProtocolError.UnknownCommand));

        text.Should().Be("IDENTIFY refused (UnknownCommand): the handler is not ours or too old; regenerate it");
    }

    private static ProjectStation StationOf(CpuModel model) =>
        StarterProject.Create("line", CpuProfiles.For(model), Two, "COM3").Stations[0];

    private static IdentifyResponse Identify(CpuModel model, byte smb6, bool modeSwitchRun) =>
        new(Two, 1, 2, 1, HandlerIdentity.CpuModelCode(model), 1, 0x3C, 116, 5, smb6, modeSwitchRun ? (byte)1 : (byte)0, 3, 2, 9, 0, 7764, 428, 1, 120);
}
