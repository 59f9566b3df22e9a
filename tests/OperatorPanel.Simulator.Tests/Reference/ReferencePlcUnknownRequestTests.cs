using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Tests.Reference;

/// <summary>A request the reference model does not execute is refused with 05 (docs/protocol-v2.md section 3), never answered as IDENTIFY.</summary>
public sealed class ReferencePlcUnknownRequestTests
{
    /// <summary>A command the protocol might gain later: parsed by Core, not (yet) executed by the model.</summary>
    private sealed record FutureRequest(Station Station, byte Sequence) : PlcRequest(Station, Sequence)
    {
        public override CommandCode Command => (CommandCode)0x0A;
    }

    private static ReferencePlc Plc() => new(new HandlerConfig(new Station(1), CpuProfiles.For(CpuModel.Cpu224), 0, HandlerConfig.DefaultWriteMask, replyDelayMs: 5));

    [Fact]
    public void TryExecute_RequestTheModelDoesNotExecute_RefusedAsUnknownCommand()
    {
        var error = Plc().TryExecute(new FutureRequest(new Station(1), 3), out var payload);

        error.Should().Be(ProtocolError.UnknownCommand);
        payload.Should().BeEmpty("nothing of IDENTIFY's reply goes out with the refusal");
    }

    [Fact]
    public void TryExecute_Identify_AnswersWithTheIdentifyPayload()
    {
        var error = Plc().TryExecute(new IdentifyRequest(new Station(1), 3), out var payload);

        error.Should().Be(ProtocolError.None);
        payload[0].Should().Be(HandlerIdentity.ProtocolVersion);
    }
}
