using System.Buffers.Binary;
using System.Collections.Immutable;

namespace OperatorPanel.Core.Ppi.S7;

/// <summary>
/// Answer PDUs as the master reads them (layouts of <see cref="S7AnswerCodec"/>). Each check returns
/// <see cref="S7PduError.None"/> or why the PDU is not the answer to the job sent; <see cref="S7PduError.Refused"/>
/// leaves the header's error class and code in <c>header</c>.
/// </summary>
public static class S7AnswerDecoder
{
    public static S7PduError TryRead(ReadOnlySpan<byte> pdu, ushort reference, IReadOnlyList<S7Item> items, out S7Header header, out ImmutableArray<S7ItemResult> results)
    {
        ArgumentNullException.ThrowIfNull(items);
        results = [];
        var error = Check(pdu, reference, S7Function.ReadVariable, items.Count, out header);
        if (error != S7PduError.None)
        {
            return error;
        }

        var data = pdu[(header.Length + header.ParameterLength)..];
        var builder = ImmutableArray.CreateBuilder<S7ItemResult>(items.Count);
        var at = 0;
        for (var i = 0; i < items.Count; i++)
        {
            if (at + 4 > data.Length)
            {
                return S7PduError.BadItem;
            }

            var code = (S7ReturnCode)data[at];
            if (code != S7ReturnCode.Success)
            {
                builder.Add(S7ItemResult.Failed(code));
                at += 4;
                continue;
            }

            var size = (S7DataSize)data[at + 1];
            var bytes = S7DataSizes.ByteCount(size, BinaryPrimitives.ReadUInt16BigEndian(data[(at + 2)..]));
            if (bytes != items[i].DataLength || at + 4 + bytes > data.Length)
            {
                return S7PduError.BadItem;
            }

            builder.Add(S7ItemResult.Of(size, data.Slice(at + 4, bytes)));
            at += 4 + bytes + (bytes % 2);
        }

        results = builder.MoveToImmutable();
        return S7PduError.None;
    }

    public static S7PduError TryWrite(ReadOnlySpan<byte> pdu, ushort reference, int itemCount, out S7Header header, out ImmutableArray<S7ReturnCode> codes)
    {
        codes = [];
        var error = Check(pdu, reference, S7Function.WriteVariable, itemCount, out header);
        if (error != S7PduError.None)
        {
            return error;
        }

        var data = pdu[(header.Length + header.ParameterLength)..];
        if (data.Length != itemCount)
        {
            return S7PduError.BadItem;
        }

        codes = [.. data.ToArray().Select(b => (S7ReturnCode)b)];
        return S7PduError.None;
    }

    /// <summary>The PDU size the CPU agreed to (parameter bytes 6-7 of its answer, libnodave _daveNegPDUlengthRequest).</summary>
    public static S7PduError TrySetupCommunication(ReadOnlySpan<byte> pdu, ushort reference, out S7Header header, out int pduSize)
    {
        pduSize = 0;
        var error = Check(pdu, reference, S7Function.SetupCommunication, null, out header);
        if (error == S7PduError.None && header.ParameterLength < 8)
        {
            return S7PduError.TooShort;
        }

        pduSize = error == S7PduError.None ? BinaryPrimitives.ReadUInt16BigEndian(pdu[(header.Length + 6)..]) : 0;
        return error;
    }

    /// <summary>STOP or RUN acknowledged: an AckData answer with error 0 whose parameters start with the function.</summary>
    public static S7PduError TryControl(ReadOnlySpan<byte> pdu, ushort reference, S7Function function, out S7Header header) =>
        Check(pdu, reference, function, null, out header);

    private static S7PduError Check(ReadOnlySpan<byte> pdu, ushort reference, S7Function function, int? itemCount, out S7Header header)
    {
        if (!S7Header.TryRead(pdu, out header, out var error))
        {
            return error;
        }

        if (header.Type is not (S7MessageType.Ack or S7MessageType.AckData))
        {
            return S7PduError.WrongMessageType;
        }

        if (header.Reference != reference)
        {
            return S7PduError.ReferenceMismatch;
        }

        if (header.Error != 0)
        {
            return S7PduError.Refused;
        }

        var parameters = pdu.Slice(header.Length, header.ParameterLength);
        if (parameters.IsEmpty || parameters[0] != (byte)function)
        {
            return S7PduError.WrongFunction;
        }

        return itemCount is { } count && (parameters.Length < 2 || parameters[1] != count) ? S7PduError.ItemCountMismatch : S7PduError.None;
    }
}
