using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Tests.Polling;

/// <summary>
/// A hand-written <see cref="IPlcLink"/> serving requests from in-memory areas per station (256 bytes each, I not
/// writable), like the handler would. Can throw, refuse, ignore writes, take time on the test clock, and records
/// every request with the clock time it was sent.
/// </summary>
internal sealed class FakePlcLink(PollingTestClock clock) : IPlcLink
{
    public const int AreaSize = 256;

    private readonly Lock _lock = new();
    private readonly Dictionary<(Station, ProtocolArea), byte[]> _memory = [];
    private readonly Dictionary<Station, Exception> _throws = [];
    private readonly Dictionary<Station, ProtocolError> _refusals = [];
    private readonly List<(PlcRequest Request, DateTimeOffset At)> _log = [];
    private readonly Dictionary<(Station, int), ImmutableArray<ReadItem>> _lists = [];
    private readonly Dictionary<(Station, int), byte[]> _copies = [];

    /// <summary>Clock time each exchange takes (the clock is advanced before the reply).</summary>
    public TimeSpan ExchangeDuration { get; set; }

    /// <summary>Called with each request before it is served, e.g. to queue a write in the middle of a cycle.</summary>
    public Action<PlcRequest>? OnExchange { get; set; }

    /// <summary>Stations whose program overwrites the panel's writes at once: the write is acknowledged, memory unchanged.</summary>
    public HashSet<Station> IgnoresWrites { get; } = [];

    /// <summary>Stations whose requests a buggy link answers with a null reply object.</summary>
    public HashSet<Station> RepliesWithNull { get; } = [];

    public IReadOnlyList<PlcRequest> Requests
    {
        get { lock (_lock) { return [.. _log.Select(e => e.Request)]; } }
    }

    public IReadOnlyList<DateTimeOffset> RequestTimes
    {
        get { lock (_lock) { return [.. _log.Select(e => e.At)]; } }
    }

    /// <summary>Stations that refuse DEFINE LIST with 04 (the lists do not fit), like a handler whose tail is full.</summary>
    public HashSet<Station> RefusesLists { get; } = [];

    /// <summary>Stations whose handler keeps no READ CHANGES copies: every READ CHANGES answers FULL.</summary>
    public HashSet<Station> KeepsNoCopies { get; } = [];

    /// <summary>Stations whose handler predates 09 READ CHANGES OF LISTS: it answers 05, unknown command.</summary>
    public HashSet<Station> LacksChangesOfLists { get; } = [];

    /// <summary>Rewrites a served reply before it reaches the engine, e.g. into one the handler should never send.</summary>
    public Func<PlcRequest, PlcResponse, PlcResponse>? Tamper { get; set; }

    /// <summary>Requests the station serves (its copy moves on) but whose reply is lost on the way: the link throws NoAnswer.</summary>
    public Func<PlcRequest, bool>? LosesReplyTo { get; set; }

    /// <summary>Forgets every list of the station and its copies, as a handler does when a long frame reaches its buffer tail.</summary>
    public void ClearLists(Station station)
    {
        lock (_lock)
        {
            foreach (var key in _lists.Keys.Where(k => k.Item1 == station).ToList())
            {
                _lists.Remove(key);
                _copies.Remove(key);
            }
        }
    }

    public int ExchangesWith(Station station) => Requests.Count(r => r.Station == station);

    public void Set(Station station, ProtocolArea area, int offset, params byte[] bytes) =>
        bytes.CopyTo(Memory(station, area), offset);

    public byte[] Memory(Station station, ProtocolArea area)
    {
        lock (_lock)
        {
            if (!_memory.TryGetValue((station, area), out var bytes))
            {
                bytes = new byte[AreaSize];
                _memory[(station, area)] = bytes;
            }

            return bytes;
        }
    }

    /// <summary>
    /// Every request to the station fails with <paramref name="exception"/>: a <see cref="PlcCommunicationException"/> is
    /// the link's failure value, as PlcLink returns it; any other exception is thrown (synchronously), as a buggy link
    /// might. Null stops it.
    /// </summary>
    public void Fail(Station station, Exception? exception)
    {
        lock (_lock)
        {
            if (exception is null) { _throws.Remove(station); } else { _throws[station] = exception; }
        }
    }

    /// <summary>Every request to the station gets an error reply; null stops it.</summary>
    public void Refuse(Station station, ProtocolError? error)
    {
        lock (_lock)
        {
            if (error is { } e) { _refusals[station] = e; } else { _refusals.Remove(station); }
        }
    }

    public Task<LinkReply> ExchangeAsync(PlcRequest request, CancellationToken cancellationToken)
    {
        lock (_lock) { _log.Add((request, clock.GetUtcNow())); }
        OnExchange?.Invoke(request);
        if (ExchangeDuration > TimeSpan.Zero)
        {
            clock.Advance(ExchangeDuration);
        }

        Exception? exception;
        ProtocolError refusal;
        lock (_lock)
        {
            exception = _throws.GetValueOrDefault(request.Station);
            refusal = _refusals.GetValueOrDefault(request.Station);
        }

        // The fake fails at once, so every failure counts as sent (a write's reply lost): the safe side.
        if (exception is PlcCommunicationException failure)
        {
            return Task.FromResult<LinkReply>(new LinkReply.Failed(failure, Sent: true));
        }

        if (exception is not null)
        {
            throw exception;
        }

        if (RepliesWithNull.Contains(request.Station))
        {
            return Task.FromResult<LinkReply>(new LinkReply.Answered(null!));
        }

        var response = refusal != ProtocolError.None ? Error(request, refusal) : Serve(request);
        response = Tamper?.Invoke(request, response) ?? response;
        if (LosesReplyTo?.Invoke(request) == true)
        {
            return Task.FromResult<LinkReply>(new LinkReply.Failed(new PlcCommunicationException(PlcErrorKind.NoAnswer, request.Station, "reply lost"), Sent: true));
        }

        return Task.FromResult<LinkReply>(new LinkReply.Answered(response));
    }

    public LinkStatistics StatisticsFor(Station station) => LinkStatistics.Empty;

    /// <summary>As the handler: FULL when asked, without a valid copy, or when the pairs would not be shorter; the copy moves on.</summary>
    private PlcResponse ServeChanges(ReadChangesRequest request)
    {
        lock (_lock)
        {
            if (!_lists.TryGetValue((request.Station, request.List), out var items))
            {
                return Error(request, ProtocolError.ListNotDefined);
            }

            byte[] data = [.. items.SelectMany(i => Memory(request.Station, i.Area).Skip(i.Offset).Take(i.Length))];
            var hadCopy = _copies.TryGetValue((request.Station, request.List), out var copy);
            if (!KeepsNoCopies.Contains(request.Station))
            {
                _copies[(request.Station, request.List)] = data;
            }

            var changed = hadCopy ? Enumerable.Range(0, data.Length).Where(i => data[i] != copy![i]).ToList() : [];
            return request.Full || !hadCopy || KeepsNoCopies.Contains(request.Station) || 2 * changed.Count >= data.Length
                ? ReadChangesResponse.Whole(request.Station, request.Sequence, [.. data])
                : ReadChangesResponse.Pairs(request.Station, request.Sequence, [.. changed.Select(i => new ChangedByte((byte)i, data[i]))]);
        }
    }

    /// <summary>
    /// As the handler: one entry per list of the mask, REREAD (and the copy invalid) when the list has no valid copy or
    /// its pairs would not be shorter than its data; else the pairs, and the copy moves on. The fit rule (reply reaching
    /// the descriptors) is not modelled: the fake's lists are small.
    /// </summary>
    private PlcResponse ServeChangesOfLists(ReadChangesOfListsRequest request)
    {
        lock (_lock)
        {
            if (LacksChangesOfLists.Contains(request.Station))
            {
                return Error(request, ProtocolError.UnknownCommand);
            }

            if (request.Lists.Any(list => !_lists.ContainsKey((request.Station, list))))
            {
                return Error(request, ProtocolError.ListNotDefined);
            }

            var entries = new List<ListChanges>();
            foreach (var list in request.Lists)
            {
                var key = (request.Station, list);
                byte[] data = [.. _lists[key].SelectMany(i => Memory(request.Station, i.Area).Skip(i.Offset).Take(i.Length))];
                var changed = _copies.TryGetValue(key, out var copy) ? Enumerable.Range(0, data.Length).Where(i => data[i] != copy[i]).ToList() : null;
                if (changed is null || KeepsNoCopies.Contains(request.Station) || 2 * changed.Count >= data.Length)
                {
                    _copies.Remove(key);
                    entries.Add(ListChanges.RereadList(list));
                    continue;
                }

                _copies[key] = data;
                entries.Add(ListChanges.Pairs(list, [.. changed.Select(i => new ChangedByte((byte)i, data[i]))]));
            }

            return new ReadChangesOfListsResponse(request.Station, request.Sequence, [.. entries]);
        }
    }

    private static ErrorResponse Error(PlcRequest request, ProtocolError error) => new(request.Station, request.Sequence, request.Command, error);

    private PlcResponse Serve(PlcRequest request)
    {
        switch (request)
        {
            case ReadRequest read:
                if (read.Items.Any(i => i.Offset + i.Length > AreaSize))
                {
                    return Error(request, ProtocolError.AddressOutOfRange);
                }

                return new ReadResponse(read.Station, read.Sequence, [.. read.Items.SelectMany(i => Memory(read.Station, i.Area).Skip(i.Offset).Take(i.Length))]);
            case DefineListRequest define:
                if (RefusesLists.Contains(define.Station))
                {
                    return Error(request, ProtocolError.BadLength);
                }

                lock (_lock)
                {
                    // A redefinition clears every list of the station first, whatever the item checks say (docs/protocol-v2.md).
                    if (_lists.ContainsKey((define.Station, define.List)))
                    {
                        ClearLists(define.Station);
                    }

                    if (define.Items.Any(i => i.Offset + i.Length > AreaSize))
                    {
                        return Error(request, ProtocolError.AddressOutOfRange);
                    }

                    _lists[(define.Station, define.List)] = define.Items;
                    _copies.Remove((define.Station, define.List));
                }

                return new DefineListResponse(define.Station, define.Sequence);
            case ReadListRequest list:
                ImmutableArray<ReadItem> items;
                lock (_lock)
                {
                    if (!_lists.TryGetValue((list.Station, list.List), out items))
                    {
                        return Error(request, ProtocolError.ListNotDefined);
                    }
                }

                return new ReadListResponse(list.Station, list.Sequence, [.. items.SelectMany(i => Memory(list.Station, i.Area).Skip(i.Offset).Take(i.Length))]);
            case ReadChangesRequest changes:
                return ServeChanges(changes);
            case ReadChangesOfListsRequest lists:
                return ServeChangesOfLists(lists);
            case WriteBlockRequest write:
                if (write.Area == ProtocolArea.I)
                {
                    return Error(request, ProtocolError.NotWritable);
                }

                var memory = Memory(write.Station, write.Area);
                if (!IgnoresWrites.Contains(write.Station))
                {
                    write.Data.CopyTo(memory, write.Offset);
                }

                return new WriteBlockResponse(write.Station, write.Sequence, [.. memory.Skip(write.Offset).Take(write.Data.Length)]);
            case WriteBitRequest bit:
                var bytes = Memory(bit.Station, bit.Area);
                if (!IgnoresWrites.Contains(bit.Station))
                {
                    bytes[bit.Offset] = (byte)(bit.Value ? bytes[bit.Offset] | (1 << bit.Bit) : bytes[bit.Offset] & ~(1 << bit.Bit));
                }

                return new WriteBitResponse(bit.Station, bit.Sequence, bytes[bit.Offset]);
            default:
                return Error(request, ProtocolError.UnknownCommand);
        }
    }
}
