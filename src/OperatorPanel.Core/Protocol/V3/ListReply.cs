using System.Collections.Immutable;

namespace OperatorPanel.Core.Protocol.V3;

/// <summary>One CHANGES entry: double word INDEX of the list data (bytes 4 x INDEX .. 4 x INDEX + 3) and its 4 bytes.</summary>
public readonly record struct ChangeEntry(byte Index, uint Value);

/// <summary>
/// The answer to READ LIST or READ LIST FULL for a list of <c>D</c> data bytes (docs/protocol.md section 2): the whole
/// data (STATUS OK), nothing changed (UNCHANGED), or the changed double words (CHANGES). <see cref="TryApply"/> turns it
/// into the list's data, given the data of the last good reply.
/// </summary>
public sealed record ListReply(ReplyStatus Status, ImmutableArray<byte> Data, ImmutableArray<ChangeEntry> Changes)
{
    /// <summary>False when <paramref name="reply"/> is not a well-formed answer for a list of <paramref name="listBytes"/>.</summary>
    public static bool TryRead(Reply reply, int listBytes, out ListReply list)
    {
        ArgumentNullException.ThrowIfNull(reply);
        list = null!;
        var payload = reply.Payload;
        switch (reply.Status)
        {
            case ReplyStatus.Ok when payload.Length == listBytes:
                list = new ListReply(ReplyStatus.Ok, payload, []);
                return true;
            case ReplyStatus.Unchanged when payload.Length == 0:
                list = new ListReply(ReplyStatus.Unchanged, [], []);
                return true;
            case ReplyStatus.Changes when payload.Length > 0 && payload.Length % Limits.ChangeEntryBytes == 0 && payload.Length < listBytes:
                var entries = Entries(payload.AsSpan());
                var words = (listBytes + 3) / 4;
                if (entries.Select((e, i) => e.Index < words && (i == 0 || e.Index > entries[i - 1].Index)).All(ok => ok))
                {
                    list = new ListReply(ReplyStatus.Changes, [], entries);
                    return true;
                }

                return false;
            default:
                return false;
        }
    }

    /// <summary>The list's data after this reply, from <paramref name="known"/> (the data of the last good reply; ignored for a whole list).</summary>
    public bool TryApply(ReadOnlySpan<byte> known, int listBytes, out ImmutableArray<byte> data)
    {
        data = Status switch
        {
            ReplyStatus.Ok => Data,
            _ when known.Length != listBytes => default,
            ReplyStatus.Unchanged => [.. known],
            _ => Patched(known, listBytes),
        };
        return !data.IsDefault;
    }

    private ImmutableArray<byte> Patched(ReadOnlySpan<byte> known, int listBytes)
    {
        var padded = new byte[((listBytes + 3) / 4) * 4];
        known.CopyTo(padded);
        foreach (var change in Changes)
        {
            System.Buffers.Binary.BinaryPrimitives.WriteUInt32BigEndian(padded.AsSpan(4 * change.Index), change.Value);
        }

        return [.. padded.AsSpan(0, listBytes)];
    }

    private static ImmutableArray<ChangeEntry> Entries(ReadOnlySpan<byte> payload)
    {
        var entries = ImmutableArray.CreateBuilder<ChangeEntry>(payload.Length / Limits.ChangeEntryBytes);
        for (var at = 0; at < payload.Length; at += Limits.ChangeEntryBytes)
        {
            entries.Add(new ChangeEntry(payload[at], System.Buffers.Binary.BinaryPrimitives.ReadUInt32BigEndian(payload[(at + 1)..])));
        }

        return entries.MoveToImmutable();
    }
}
