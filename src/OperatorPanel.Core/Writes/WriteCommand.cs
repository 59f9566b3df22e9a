using System.Collections.Immutable;
using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Writes;

/// <summary>Builds the WRITE or WRITE BIT request of a <see cref="WriteRequest"/> and judges the reply (docs/protocol-v2.md, commands 03 and 04).</summary>
internal static class WriteCommand
{
    /// <summary>
    /// Checks what can be checked on the PC: the area must be one the link writes (Q, M and V: the handler never writes
    /// I or SM, docs/protocol.md section 3, 83), and with a known CPU the address must pass <see cref="AddressRules.Check"/>.
    /// Otherwise the PLC's own NotWritable and AddressOutOfRange replies decide.
    /// </summary>
    public static bool TryBuild(
        WriteRequest request,
        CpuProfile? cpu,
        [NotNullWhen(true)] out PlcRequest? plcRequest,
        [NotNullWhen(false)] out WriteOutcome.Failed? refusal)
    {
        ArgumentNullException.ThrowIfNull(request);
        plcRequest = null;
        var address = request.Address;
        var error = cpu is null ? null : AddressRules.Check(address, cpu, AddressUse.Write);
        if (LinkAreas.WriteRefusal(address, Transport.LinkProtocol.Freeport, "SM") is { } notWritten)
        {
            error ??= new AddressError(AddressErrorKind.NotWritable, notWritten);
        }

        if (error is not null)
        {
            refusal = new WriteOutcome.Failed(error.Message, WriteFailureKind.InvalidRequest);
            return false;
        }

        var protocolArea = ProtocolAreaExtensions.FromMemoryArea(address.Area)!.Value;
        plcRequest = request.BitValue is { } bit
            ? new WriteBitRequest(request.Station, protocolArea, address.ByteOffset, address.Bit!.Value, bit)
            : new WriteBlockRequest(request.Station, protocolArea, address.ByteOffset, request.Data);
        refusal = null;
        return true;
    }

    /// <summary>
    /// Judges the reply. <paramref name="readBackBytes"/> receives the bytes the PLC now holds from the address's first
    /// byte (the whole byte for a bit), for the value store; default when the reply carried none.
    /// </summary>
    public static WriteOutcome Interpret(WriteRequest request, PlcResponse? response, out ImmutableArray<byte> readBackBytes)
    {
        ArgumentNullException.ThrowIfNull(request);
        readBackBytes = default;
        switch (response)
        {
            case WriteBlockResponse block when request.BitValue is null:
                readBackBytes = block.ReadBack;
                return Judge(request.Value, block.ReadBack);
            case WriteBitResponse bitReply when request.BitValue is not null:
                readBackBytes = [bitReply.ReadBack];
                return Judge(request.Value, ValueStore.Extract(request.Address, [bitReply.ReadBack]));
            case null:
                return new WriteOutcome.Failed($"the link returned no reply object for a write to {request.Station}", WriteFailureKind.UnexpectedReply);
            case ErrorResponse refused:
                return new WriteOutcome.Failed($"{request.Station} refused the write: {ProtocolErrorText.Describe(refused.Error)}", WriteFailureKind.RefusedByPlc);
            default:
                return new WriteOutcome.Failed($"{request.Station} answered a write with a {response.Command} reply", WriteFailureKind.UnexpectedReply);
        }
    }

    private static WriteOutcome Judge(ImmutableArray<byte> expected, ImmutableArray<byte> readBack) =>
        expected.AsSpan().SequenceEqual(readBack.AsSpan())
            ? new WriteOutcome.Confirmed(readBack)
            : new WriteOutcome.ReadBackMismatch(expected, readBack);
}
