using System.Buffers.Binary;
using System.Collections.Immutable;

namespace OperatorPanel.Core.Ppi.S7;

/// <summary>Job PDUs as the CPU side reads them (the layouts of <see cref="S7JobCodec"/>; docs/ppi.md section 5).</summary>
public static class S7JobDecoder
{
    /// <summary>Reads a job PDU; false with why when it is not one (then nothing should be answered).</summary>
    public static bool TryDecode(ReadOnlySpan<byte> pdu, out S7Job job, out S7PduError error)
    {
        job = null!;
        if (!S7Header.TryRead(pdu, out var header, out error))
        {
            return false;
        }

        if (header.Type != S7MessageType.Job || header.ParameterLength == 0)
        {
            error = header.Type != S7MessageType.Job ? S7PduError.WrongMessageType : S7PduError.TooShort;
            return false;
        }

        var parameters = pdu.Slice(S7Header.JobLength, header.ParameterLength);
        var data = pdu[(S7Header.JobLength + header.ParameterLength)..];
        job = (S7Function)parameters[0] switch
        {
            S7Function.ReadVariable => ReadJob(header.Reference, parameters, data, ref error),
            S7Function.WriteVariable => WriteJob(header.Reference, parameters, data, ref error),
            S7Function.SetupCommunication when parameters.Length >= 8 =>
                new S7Job.SetupCommunication(header.Reference, BinaryPrimitives.ReadUInt16BigEndian(parameters[6..])),
            S7Function.PlcStop or S7Function.PlcControl when parameters.IndexOf(S7JobCodec.ProgramName) > 0 =>
                new S7Job.Control(header.Reference, (S7Function)parameters[0]),
            _ => new S7Job.Unsupported(header.Reference, parameters[0]),
        };
        return error == S7PduError.None;
    }

    private static S7Job.Read ReadJob(ushort reference, ReadOnlySpan<byte> parameters, ReadOnlySpan<byte> data, ref S7PduError error)
    {
        error = TryItems(parameters, out var items) && data.IsEmpty ? S7PduError.None : S7PduError.BadItem;
        return new S7Job.Read(reference, items);
    }

    private static S7Job.Write WriteJob(ushort reference, ReadOnlySpan<byte> parameters, ReadOnlySpan<byte> data, ref S7PduError error)
    {
        var writes = ImmutableArray.CreateBuilder<S7WriteItem>();
        var problems = ImmutableArray.CreateBuilder<S7ReturnCode>();
        error = TryItems(parameters, out var items) ? S7PduError.None : S7PduError.BadItem;
        var at = 0;
        for (var i = 0; i < items.Length && error == S7PduError.None; i++)
        {
            if (at + 4 > data.Length)
            {
                error = S7PduError.BadItem;
                break;
            }

            var size = (S7DataSize)data[at + 1];
            var bytes = S7DataSizes.ByteCount(size, BinaryPrimitives.ReadUInt16BigEndian(data[(at + 2)..]));
            if (bytes < 0 || at + 4 + bytes > data.Length)
            {
                error = S7PduError.BadItem;
                break;
            }

            var value = data.Slice(at + 4, bytes);
            var fits = bytes == items[i].DataLength;
            writes.Add(new S7WriteItem(items[i], fits ? [.. value] : [.. new byte[items[i].DataLength]]));
            problems.Add(fits ? S7ReturnCode.Success : S7ReturnCode.DataTypeInconsistent);
            at += 4 + bytes + (bytes % 2 == 1 && i < items.Length - 1 ? 1 : 0);
        }

        return new S7Job.Write(reference, writes.ToImmutable(), problems.ToImmutable());
    }

    private static bool TryItems(ReadOnlySpan<byte> parameters, out ImmutableArray<S7Item> items)
    {
        items = [];
        if (parameters.Length < 2 || parameters[1] == 0 || parameters.Length != 2 + (parameters[1] * S7Item.EncodedLength))
        {
            return false;
        }

        var builder = ImmutableArray.CreateBuilder<S7Item>(parameters[1]);
        for (var at = 2; at < parameters.Length; at += S7Item.EncodedLength)
        {
            var item = parameters.Slice(at, S7Item.EncodedLength);
            if (item[0] != 0x12 || item[1] != 0x0A || item[2] != 0x10)
            {
                return false;
            }

            builder.Add(new S7Item(
                (S7TransportSize)item[3],
                BinaryPrimitives.ReadUInt16BigEndian(item[4..]),
                BinaryPrimitives.ReadUInt16BigEndian(item[6..]),
                (S7Area)item[8],
                (item[9] << 16) | (item[10] << 8) | item[11]));
        }

        items = builder.MoveToImmutable();
        return true;
    }

}
