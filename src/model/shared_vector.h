#pragma once
// A std::vector whose copies share their elements until one of them is changed (copy on write), as
// Qt's implicitly shared containers do. The document keeps the keys of each track in one, so that a
// copy of a whole scene (the autosave's snapshot, a command's saved state) costs one reference count
// per track rather than a copy of every key: a ten-minute capture of 31 joints holds 2.2 million keys.
//
// Reading through a const reference never copies. Any access through a non-const reference (non-const
// operator[], begin, front, edit, …) first makes the elements this object's own if they are shared;
// references it hands out are valid until the next copy of this object is taken, as for QList.
//
// A copy may be read on another thread while the original is changed on its own: the elements are
// shared read-only, and changing the original copies them first.

#include <atomic>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <utility>
#include <vector>

namespace gyre::model {

template <class T>
class SharedVector {
public:
    using value_type = T;
    using size_type = std::size_t;
    using iterator = typename std::vector<T>::iterator;
    using const_iterator = typename std::vector<T>::const_iterator;

    SharedVector() = default;
    SharedVector(std::vector<T> elements) // NOLINT(google-explicit-constructor): stands in for the vector
        : elements_(std::make_shared<std::vector<T>>(std::move(elements)))
    {
    }
    SharedVector(std::initializer_list<T> elements)
        : SharedVector(std::vector<T>(elements))
    {
    }

    // The elements, never copied.
    const std::vector<T>& vector() const { return elements_ ? *elements_ : noElements(); }
    operator const std::vector<T>&() const { return vector(); } // NOLINT(google-explicit-constructor)

    // The elements, this object's own: copied first if another SharedVector shares them.
    std::vector<T>& edit()
    {
        if (!elements_) {
            elements_ = std::make_shared<std::vector<T>>();
        } else if (elements_.use_count() > 1) {
            elements_ = std::make_shared<std::vector<T>>(*elements_);
        } else {
            // The last other owner may have let go on another thread: see its reads before writing.
            std::atomic_thread_fence(std::memory_order_acquire);
        }
        return *elements_;
    }

    // Whether `other` reads the very same elements (both empty counts only if they share storage).
    bool sharesElementsWith(const SharedVector& other) const
    {
        return elements_ != nullptr && elements_ == other.elements_;
    }

    size_type size() const { return vector().size(); }
    bool empty() const { return vector().empty(); }
    const T& operator[](size_type index) const { return vector()[index]; }
    const T& at(size_type index) const { return vector().at(index); }
    const T& front() const { return vector().front(); }
    const T& back() const { return vector().back(); }
    const_iterator begin() const { return vector().begin(); }
    const_iterator end() const { return vector().end(); }
    const_iterator cbegin() const { return vector().cbegin(); }
    const_iterator cend() const { return vector().cend(); }

    T& operator[](size_type index) { return edit()[index]; }
    T& front() { return edit().front(); }
    T& back() { return edit().back(); }
    iterator begin() { return edit().begin(); }
    iterator end() { return edit().end(); }
    void reserve(size_type count) { edit().reserve(count); }
    void resize(size_type count) { edit().resize(count); }
    void push_back(T element) { edit().push_back(std::move(element)); }
    template <class... Arguments>
    T& emplace_back(Arguments&&... arguments)
    {
        return edit().emplace_back(std::forward<Arguments>(arguments)...);
    }
    void clear() { elements_.reset(); }

    friend bool operator==(const SharedVector& a, const SharedVector& b) { return a.vector() == b.vector(); }
    friend bool operator==(const SharedVector& a, const std::vector<T>& b) { return a.vector() == b; }

private:
    static const std::vector<T>& noElements()
    {
        static const std::vector<T> none;
        return none;
    }

    std::shared_ptr<std::vector<T>> elements_; // null when empty and never changed
};

} // namespace gyre::model
