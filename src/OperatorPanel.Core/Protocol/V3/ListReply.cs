using System.Collections.Immutable;

namespace OperatorPanel.Core.Protocol.V3;

/// <summary>One CHANGES entry: slot INDEX and its window's 4 bytes now (the item's LENGTH bytes first).</summary>
public readonly record struct ChangeEntry(byte Index, uint Value);

/// <summary>
/// The answer to READ LIST or READ LIST FULL for a list planned as <see cref="ListPlan"/> (docs/protocol.md section 2):
/// the whole data (STATUS OK), nothing changed (UNCHANGED), or the changed slots' windows (CHANGES). <see cref="TryApply"/>
/// turns it into the list's data, given the data of the last good reply.
/// </summary>
public sealed record ListReply(ReplyStatus Status, ImmutableArray<byte> Data, ImmutableArray<ChangeEntry> Changes)
{
    /// <summary>False when <paramref name="reply"/> is not a well-formed answer for the list of <paramref name="plan"/>.</summary>
    public static bool TryRead(Reply reply, ListPlan plan, out ListReply list)
    {
        ArgumentNullException.ThrowIfNull(reply);
        ArgumentNullException.ThrowIfNull(plan);
        var listBytes = plan.DataBytes;
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
                if (entries.Select((e, i) => e.Index < plan.Items.Length && (i == 0 || e.Index > entries[i - 1].Index)).All(ok => ok))
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
    public bool TryApply(ReadOnlySpan<byte> known, ListPlan plan, out ImmutableArray<byte> data)
    {
        ArgumentNullException.ThrowIfNull(plan);
        data = Status switch
        {
            ReplyStatus.Ok => Data,
            _ when known.Length != plan.DataBytes => default,
            ReplyStatus.Unchanged => [.. known],
            _ => Patched(known, plan),
        };
        return !data.IsDefault;
    }

    /// <summary>Each entry's window: its first LENGTH bytes are the slot's item bytes (the rest of the window is not in the list).</summary>
    private ImmutableArray<byte> Patched(ReadOnlySpan<byte> known, ListPlan plan)
    {
        var patched = known.ToArray();
        Span<byte> window = stackalloc byte[4];
        foreach (var change in Changes)
        {
            System.Buffers.Binary.BinaryPrimitives.WriteUInt32BigEndian(window, change.Value);
            window[..plan.Items[change.Index].Length].CopyTo(patched.AsSpan(plan.Starts[change.Index]));
        }

        return [.. patched];
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
